// GTE geometry commands: perspective transformation (RTPS/RTPT), NCLIP, OP, MVMVA, SQR,
// AVSZ3/AVSZ4 and the general-purpose interpolations GPF/GPL (psx-spx "GTE Coordinate
// Calculation Commands", "GTE General Purpose Calculation Commands").
#include <algorithm>

#include "core/gte/gte.h"
#include "core/gte/gte_arith.h"
#include "core/gte/gte_divide.h"

namespace psx {

// RTPS for one vertex: [MAC1..3] = (TR*1000h + RT*V) SAR (sf*12), SZ3 = MAC3 SAR ((1-sf)*12),
// then the projection SXY2 = (H/SZ3)*IR1/2 + OFX/OFY and, for the last vertex, depth cueing.
// Inlined into RTPS and RTPT (a call per vertex cost RTPT about a sixth of its time).
[[gnu::always_inline]] inline void Gte::rtp(const Vec16& v, Op op, bool last) {
  set_mac_ir<1>(dot_row<1>(r_.rt, v, r_.tr[0]), op);
  set_mac_ir<2>(dot_row<2>(r_.rt, v, r_.tr[1]), op);
  const s64 z = dot_row<3>(r_.rt, v, r_.tr[2]);
  r_.mac[3] = s32(z >> op.shift);
  // IR3 is clamped from MAC3, but its FLAG bit 22 tests "MAC3 SAR 12" against -8000h..7FFFh
  // whatever sf and lm are (psx-spx "RTPS/RTPT").
  const s64 z12 = z >> 12;
  if (z12 < -0x8000 || z12 > 0x7FFF) r_.flag |= kFlagIr3;
  r_.ir[3] = s16(std::clamp(r_.mac[3], op.lm ? 0 : -0x8000, 0x7FFF));
  push_sz(z12);

  u32 q = 0x1FFFF;
  if (gte_divide_overflows(r_.h, r_.sz[3])) {
    r_.flag |= kFlagDivide;
  } else {
    q = gte_divide(r_.h, r_.sz[3]);
  }
  const s64 sx = check_mac0(s64(q) * r_.ir[1] + r_.ofx);
  const s64 sy = check_mac0(s64(q) * r_.ir[2] + r_.ofy);
  push_sxy(sx >> 16, sy >> 16);
  if (last) {
    const s64 dq = s64(q) * r_.dqa + r_.dqb;  // MAC0 = (H/SZ3)*DQA+DQB, IR0 = MAC0/1000h
    set_mac0(dq);
    set_ir0(dq >> 12);
  }
}

void Gte::rtps(Op op) { rtp(r_.v[0], op, true); }

void Gte::rtpt(Op op) {
  rtp(r_.v[0], op, false);
  rtp(r_.v[1], op, false);
  rtp(r_.v[2], op, true);
}

// MAC0 = SX0*SY1 + SX1*SY2 + SX2*SY0 - SX0*SY2 - SX1*SY0 - SX2*SY1 (twice the signed area).
void Gte::nclip() {
  s64 x[3], y[3];
  for (int k = 0; k < 3; ++k) {
    x[k] = s16(r_.sxy[k]);
    y[k] = s16(r_.sxy[k] >> 16);
  }
  set_mac0(x[0] * y[1] + x[1] * y[2] + x[2] * y[0] - x[0] * y[2] - x[1] * y[0] - x[2] * y[1]);
}

// OP: cross product of the RT diagonal (D1,D2,D3) = (RT11,RT22,RT33) and IR.
void Gte::op_cross(Op op) {
  const s64 d1 = r_.rt[0][0], d2 = r_.rt[1][1], d3 = r_.rt[2][2];
  const s64 ir1 = r_.ir[1], ir2 = r_.ir[2], ir3 = r_.ir[3];
  set_mac_ir<1>(ir3 * d2 - ir2 * d3, op);
  set_mac_ir<2>(ir1 * d3 - ir3 * d1, op);
  set_mac_ir<3>(ir2 * d1 - ir1 * d2, op);
}

// MVMVA: MAC = (T*1000h + M*V) SAR (sf*12) with M (bits 17-18) = RT, LLM, LCM or the reserved
// "garbage" matrix; V (bits 15-16) = V0, V1, V2 or IR; T (bits 13-14) = TR, BK, FC (buggy) or 0.
void Gte::mvmva(u32 command, Op op) {
  const u32 mx = (command >> 17) & 3, vx = (command >> 15) & 3, cv = (command >> 13) & 3;
  Matrix garbage;
  const Matrix* m = &r_.rt;
  if (mx == 1) m = &r_.llm;
  if (mx == 2) m = &r_.lcm;
  if (mx == 3) {
    // Reserved selection: row 1 = -(R SHL 4), R SHL 4, IR0; rows 2 and 3 repeat RT13 and RT22.
    const s16 r = s16((r_.rgbc & 0xFF) << 4);
    garbage = {{{s16(-r), r, r_.ir[0]},
                {r_.rt[0][2], r_.rt[0][2], r_.rt[0][2]},
                {r_.rt[1][1], r_.rt[1][1], r_.rt[1][1]}}};
    m = &garbage;
  }
  const Vec16 v = vx < 3 ? r_.v[vx] : ir_vector();
  static constexpr Vec32 kNone{};
  switch (cv) {
    case 0: mul_mat_vec(*m, v, r_.tr, op); break;
    case 1: mul_mat_vec(*m, v, r_.bk, op); break;
    case 2: mul_mat_vec_fc_bug(*m, v, op); break;
    default: mul_mat_vec(*m, v, kNone, op); break;
  }
}

// MVMVA with FC as translation: the hardware computes FC*1000h + Mi1*VX, which only sets
// flags (IR saturation checked as if lm=0), then keeps just Mi2*VY + Mi3*VZ as the result.
template <int i>
void Gte::fc_bug_row(const Matrix& m, const Vec16& v, Op op) {
  const s64 first = check_mac<i>((s64(r_.fc[i - 1]) << 12) + s32(m[i - 1][0]) * s32(v[0]));
  set_ir<i>(s32(first >> op.shift), false);
  const s64 rest = check_mac<i>(s64(s32(m[i - 1][1]) * s32(v[1])));
  set_mac_ir<i>(check_mac<i>(rest + s32(m[i - 1][2]) * s32(v[2])), op);
}

void Gte::mul_mat_vec_fc_bug(const Matrix& m, const Vec16& v, Op op) {
  fc_bug_row<1>(m, v, op);
  fc_bug_row<2>(m, v, op);
  fc_bug_row<3>(m, v, op);
}

// SQR: [MAC1..3] = [IR1..3]^2 SAR (sf*12).
void Gte::sqr(Op op) {
  set_mac_ir<1>(s32(r_.ir[1]) * s32(r_.ir[1]), op);
  set_mac_ir<2>(s32(r_.ir[2]) * s32(r_.ir[2]), op);
  set_mac_ir<3>(s32(r_.ir[3]) * s32(r_.ir[3]), op);
}

// OTZ = MAC0/1000h saturated to 0..FFFFh (FLAG 18, shared with SZ3).
void Gte::set_otz(s64 mac0) {
  const s64 v = mac0 >> 12;
  if (v < 0 || v > 0xFFFF) r_.flag |= kFlagSz3Otz;
  r_.otz = u16(std::clamp<s64>(v, 0, 0xFFFF));
}

// AVSZ3: MAC0 = ZSF3*(SZ1+SZ2+SZ3), OTZ = MAC0/1000h (average Z for ordering tables).
void Gte::avsz3() {
  const s64 sum = s64(r_.zsf3) * (s64(r_.sz[1]) + r_.sz[2] + r_.sz[3]);
  set_mac0(sum);
  set_otz(sum);
}

// AVSZ4: MAC0 = ZSF4*(SZ0+SZ1+SZ2+SZ3), OTZ = MAC0/1000h.
void Gte::avsz4() {
  const s64 sum = s64(r_.zsf4) * (s64(r_.sz[0]) + r_.sz[1] + r_.sz[2] + r_.sz[3]);
  set_mac0(sum);
  set_otz(sum);
}

// GPF: [MAC1..3] = IR0*[IR1..3] SAR (sf*12), then a colour FIFO push.
void Gte::gpf(Op op) {
  const s32 ir0 = r_.ir[0];
  set_mac_ir<1>(ir0 * r_.ir[1], op);
  set_mac_ir<2>(ir0 * r_.ir[2], op);
  set_mac_ir<3>(ir0 * r_.ir[3], op);
  push_rgb_from_mac();
}

// GPL: [MAC1..3] = ([MAC1..3] SHL (sf*12) + IR0*[IR1..3]) SAR (sf*12), then a colour push.
void Gte::gpl(Op op) {
  const s32 ir0 = r_.ir[0];
  set_mac_ir<1>(check_mac<1>((s64(r_.mac[1]) << op.shift) + ir0 * r_.ir[1]), op);
  set_mac_ir<2>(check_mac<2>((s64(r_.mac[2]) << op.shift) + ir0 * r_.ir[2]), op);
  set_mac_ir<3>(check_mac<3>((s64(r_.mac[3]) << op.shift) + ir0 * r_.ir[3]), op);
  push_rgb_from_mac();
}

}  // namespace psx
