// GTE division: the perspective reciprocal H/SZ3 of RTPS/RTPT, computed as the hardware does
// with an unsigned Newton-Raphson step seeded from a 257-entry table (psx-spx "GTE Division
// Inaccuracy"). The result is unsigned 1.16 fixed point, 0..1FFFFh.
#pragma once
#include <array>
#include <algorithm>
#include <bit>

#include "core/types.h"

namespace psx {

// unr_table[i] = max(0, (40000h/(i+100h)+1)/2 - 101h): the reciprocal seed for a divisor
// normalised to 8000h..FFFFh, i = (d-7FC0h) SHR 7 = 0..100h.
inline constexpr std::array<u8, 257> kGteUnrTable = [] {
  std::array<u8, 257> t{};
  for (int i = 0; i < 257; ++i) t[i] = u8(std::max(0, (0x40000 / (i + 0x100) + 1) / 2 - 0x101));
  return t;
}();

// The divide overflows (result 1FFFFh, FLAG bit 17) unless H < SZ3*2; this covers SZ3 = 0.
constexpr bool gte_divide_overflows(u32 h, u32 sz3) { return h >= sz3 * 2; }

// H/SZ3 for 16-bit H and SZ3 that do not overflow.
constexpr u32 gte_divide(u32 h, u32 sz3) {
  const int z = std::countl_zero(u16(sz3));        // normalise the divisor to 8000h..FFFFh
  const u64 n = u64(h) << z;
  u32 d = sz3 << z;
  const u32 u = kGteUnrTable[(d - 0x7FC0) >> 7] + 0x101;  // seed 1/d, 101h..200h
  d = (0x2000080 - d * u) >> 8;                           // 2 - d*u: one Newton-Raphson step
  d = (0x0000080 + d * u) >> 8;                           // refined 1/d, 10000h..20000h
  return u32(std::min<u64>(0x1FFFF, (n * d + 0x8000) >> 16));
}

}  // namespace psx
