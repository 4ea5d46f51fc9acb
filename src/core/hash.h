// FNV-1a 64-bit hashing: identities of BIOS images and loaded programs in save-state headers,
// checksums of save-state payloads, and the RAM/VRAM hashes determinism tests compare.
#pragma once
#include <cstddef>

#include "core/types.h"

namespace psx {

constexpr u64 kFnvOffset = 0xCBF29CE484222325ull;

inline u64 fnv1a(const void* data, size_t n, u64 h = kFnvOffset) {
  const u8* p = static_cast<const u8*>(data);
  for (size_t i = 0; i < n; ++i) {
    h ^= p[i];
    h *= 0x100000001B3ull;
  }
  return h;
}

}  // namespace psx
