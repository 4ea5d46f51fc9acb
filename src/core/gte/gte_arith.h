// GTE arithmetic shared by the commands: the 44-bit MAC1-3 overflow checks, the 32-bit MAC0
// checks, IR/colour/SZ/SXY saturation with their FLAG bits, and the matrix-times-vector
// datapath (psx-spx "GTE Saturation", "GTE Coordinate Calculation Commands").
// Private to src/core/gte: included only by the command files, so these inline.
#pragma once
#include <algorithm>

#include "core/gte/gte.h"

namespace psx {

// MAC1-3 accumulate in 44 bits: each partial sum is checked against the 44-bit range (FLAG
// 30-28 positive, 27-25 negative) and wraps to 44 bits before the next term is added.
template <int i>
inline s64 Gte::check_mac(s64 v) {
  // In range iff v + 2^43 fits in 44 unsigned bits: one well-predicted test on the fast path.
  if (u64(v + (s64(1) << 43)) >> 44) [[unlikely]] {
    r_.flag |= v > 0 ? kFlagMac1Pos >> (i - 1) : kFlagMac1Neg >> (i - 1);
  }
  return (v << 20) >> 20;
}

// IR1-3 saturate to -8000h..7FFFh, or 0..7FFFh when lm is set (FLAG 24-22).
template <int i>
inline void Gte::set_ir(s32 v, bool lm) {
  const s32 lo = lm ? 0 : -0x8000;
  if (u32(v) - u32(lo) > u32(0x7FFF - lo)) [[unlikely]] {  // unsigned: v - lo may not fit in s32
    v = v < lo ? lo : 0x7FFF;
    r_.flag |= kFlagIr1 >> (i - 1);
  }
  r_.ir[i] = s16(v);
}

// MACi = value SAR (sf*12), truncated to 32 bits; IRi = saturated MACi.
template <int i>
inline void Gte::set_mac_ir(s64 v, Op op) {
  const s32 mac = s32(v >> op.shift);
  r_.mac[i] = mac;
  set_ir<i>(mac, op.lm);
}

// MAC0 results are checked against the 32-bit range (FLAG 16 positive, 15 negative).
inline s64 Gte::check_mac0(s64 v) {
  if (v > s64(INT32_MAX)) {
    r_.flag |= kFlagMac0Pos;
  } else if (v < s64(INT32_MIN)) {
    r_.flag |= kFlagMac0Neg;
  }
  return v;
}

inline void Gte::set_mac0(s64 v) { r_.mac[0] = s32(check_mac0(v)); }

// IR0 saturates to 0..1000h (FLAG 12).
inline void Gte::set_ir0(s64 v) {
  if (v < 0 || v > 0x1000) r_.flag |= kFlagIr0;
  r_.ir[0] = s16(std::clamp<s64>(v, 0, 0x1000));
}

// Screen Z FIFO: SZ0 <- SZ1 <- SZ2 <- SZ3 <- value saturated to 0..FFFFh (FLAG 18).
inline void Gte::push_sz(s64 z) {
  if (z < 0 || z > 0xFFFF) r_.flag |= kFlagSz3Otz;
  r_.sz[0] = r_.sz[1];
  r_.sz[1] = r_.sz[2];
  r_.sz[2] = r_.sz[3];
  r_.sz[3] = u16(std::clamp<s64>(z, 0, 0xFFFF));
}

// Screen XY FIFO: X and Y saturate to -400h..3FFh (FLAG 14 and 13).
inline void Gte::push_sxy(s64 x, s64 y) {
  if (x < -0x400 || x > 0x3FF) r_.flag |= kFlagSx2;
  if (y < -0x400 || y > 0x3FF) r_.flag |= kFlagSy2;
  const u32 sx = u16(std::clamp<s64>(x, -0x400, 0x3FF));
  const u32 sy = u16(std::clamp<s64>(y, -0x400, 0x3FF));
  r_.sxy[0] = r_.sxy[1];
  r_.sxy[1] = r_.sxy[2];
  r_.sxy[2] = sx | (sy << 16);
}

// Colour FIFO: [MAC1,MAC2,MAC3] / 16 saturated to 0..FFh (FLAG 21-19), with RGBC's CODE byte.
inline void Gte::push_rgb_from_mac() {
  u32 c = r_.rgbc & 0xFF000000;
  for (int k = 0; k < 3; ++k) {
    s32 v = r_.mac[k + 1] >> 4;
    if (v < 0 || v > 0xFF) {
      r_.flag |= kFlagColorR >> k;
      v = std::clamp(v, 0, 0xFF);
    }
    c |= u32(v) << (8 * k);
  }
  r_.rgb[0] = r_.rgb[1];
  r_.rgb[1] = r_.rgb[2];
  r_.rgb[2] = c;
}

// One row of "T*1000h + M*V" (row i-1 of M): every partial sum goes through the 44-bit check.
template <int i>
inline s64 Gte::dot_row(const Matrix& m, const Vec16& v, s32 t) {
  const s64 p0 = s32(m[i - 1][0]) * s32(v[0]), p1 = s32(m[i - 1][1]) * s32(v[1]), p2 = s32(m[i - 1][2]) * s32(v[2]);
  // With -2^30 <= T < 2^30 no partial sum can leave the 44-bit range: |T*1000h| < 2^42 and each
  // product is at most 8000h*8000h = 2^30, so the checks would neither flag nor wrap.
  if (u32(t) + 0x40000000u < 0x80000000u) [[likely]] return (s64(t) << 12) + p0 + p1 + p2;
  s64 a = check_mac<i>((s64(t) << 12) + p0);
  a = check_mac<i>(a + p1);
  return check_mac<i>(a + p2);
}

// [MAC1..3] = (T*1000h + M*V) SAR (sf*12); [IR1..3] = saturated MAC1..3.
inline void Gte::mul_mat_vec(const Matrix& m, const Vec16& v, const Vec32& t, Op op) {
  set_mac_ir<1>(dot_row<1>(m, v, t[0]), op);
  set_mac_ir<2>(dot_row<2>(m, v, t[1]), op);
  set_mac_ir<3>(dot_row<3>(m, v, t[2]), op);
}

}  // namespace psx
