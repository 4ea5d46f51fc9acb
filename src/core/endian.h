// Little-endian loads and stores in byte buffers: the R3000A runs little-endian, and so is every
// structure the console and its files hold (RAM words, PS-X EXE headers, ISO 9660 "both-endian"
// fields' LE half, sector EDC, RIFF/WAVE chunks).
#pragma once
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

}  // namespace psx
