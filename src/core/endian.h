// Little-endian loads and stores in byte buffers: the R3000A runs little-endian, and so is every
// structure the console and its files hold (RAM words, PS-X EXE headers, ISO 9660 "both-endian"
// fields' LE half, sector EDC, RIFF/WAVE chunks).
#pragma once
#include <bit>
#include <cstring>

#include "core/types.h"

namespace psx {

inline u16 load_le16(const u8* p) { return static_cast<u16>(p[0] | p[1] << 8); }
inline u32 load_le32(const u8* p) { return p[0] | p[1] << 8 | p[2] << 16 | static_cast<u32>(p[3]) << 24; }

inline void store_le16(u8* p, u16 v) {
  p[0] = u8(v);
  p[1] = u8(v >> 8);
}
inline void store_le32(u8* p, u32 v) {
  p[0] = u8(v);
  p[1] = u8(v >> 8);
  p[2] = u8(v >> 16);
  p[3] = u8(v >> 24);
}

// n words at once (DMA blocks): on a little-endian host the words already have the layout the
// buffer takes.
inline void store_le32_words(u8* p, const u32* words, size_t n) {
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(p, words, n * 4);
  } else {
    for (size_t i = 0; i < n; ++i) store_le32(p + 4 * i, words[i]);
  }
}
inline void load_le32_words(u32* words, const u8* p, size_t n) {
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(words, p, n * 4);
  } else {
    for (size_t i = 0; i < n; ++i) words[i] = load_le32(p + 4 * i);
  }
}

}  // namespace psx
