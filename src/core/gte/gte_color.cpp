// GTE lighting and depth-cueing commands: NCS/NCT, NCCS/NCCT, NCDS/NCDT, CC, CDP, DPCS/DPCT,
// INTPL and DCPL (psx-spx "GTE Lighting and Color Commands").
#include "core/gte/gte.h"
#include "core/gte/gte_arith.h"

namespace psx {

namespace {
s64 channel(u32 color, int k) { return (color >> (8 * k)) & 0xFF; }
}  // namespace

// [MAC1..3] = MAC + (FC-MAC)*IR0: first IR = (FC*1000h - MAC) SAR (sf*12), saturated as if
// lm=0, then MAC = (IR*IR0 + MAC) SAR (sf*12) with IR saturated per lm.
void Gte::interpolate_color(s64 mac1, s64 mac2, s64 mac3, Op op) {
  const Op no_lm{op.shift, false};
  set_mac_ir<1>(check_mac<1>((s64(r_.fc[0]) << 12) - mac1), no_lm);
  set_mac_ir<2>(check_mac<2>((s64(r_.fc[1]) << 12) - mac2), no_lm);
  set_mac_ir<3>(check_mac<3>((s64(r_.fc[2]) << 12) - mac3), no_lm);
  const s32 ir0 = r_.ir[0];
  set_mac_ir<1>(check_mac<1>(s64(ir0 * r_.ir[1]) + mac1), op);
  set_mac_ir<2>(check_mac<2>(s64(ir0 * r_.ir[2]) + mac2), op);
  set_mac_ir<3>(check_mac<3>(s64(ir0 * r_.ir[3]) + mac3), op);
}

// [IR1..3] = [MAC1..3] = (BK*1000h + LCM*IR) SAR (sf*12): light intensities to colour.
void Gte::color_ir(Op op) { mul_mat_vec(r_.lcm, ir_vector(), r_.bk, op); }

// [IR1..3] = (LLM*V) SAR (sf*12), then the colour step: the shared front of the NCx commands.
void Gte::light_color(const Vec16& normal, Op op) {
  static constexpr Vec32 kNone{};
  mul_mat_vec(r_.llm, normal, kNone, op);
  color_ir(op);
}

// NCCx/CC tail: [MAC1..3] = ([R,G,B]*[IR1..3]) SHL 4 SAR (sf*12), colour FIFO push.
void Gte::color_times_ir(Op op) {
  set_mac_ir<1>((channel(r_.rgbc, 0) * r_.ir[1]) << 4, op);
  set_mac_ir<2>((channel(r_.rgbc, 1) * r_.ir[2]) << 4, op);
  set_mac_ir<3>((channel(r_.rgbc, 2) * r_.ir[3]) << 4, op);
  push_rgb_from_mac();
}

// NCDx/CDP tail: ([R,G,B]*[IR1..3]) SHL 4 depth-cued towards FC, colour FIFO push.
void Gte::depth_cue_color_times_ir(Op op) {
  interpolate_color((channel(r_.rgbc, 0) * r_.ir[1]) << 4, (channel(r_.rgbc, 1) * r_.ir[2]) << 4,
                    (channel(r_.rgbc, 2) * r_.ir[3]) << 4, op);
  push_rgb_from_mac();
}

// DPCS on a given colour: [R,G,B] SHL 16 depth-cued towards FC.
void Gte::depth_cue(u32 color, Op op) {
  interpolate_color(channel(color, 0) << 16, channel(color, 1) << 16, channel(color, 2) << 16, op);
  push_rgb_from_mac();
}

void Gte::dpcs(Op op) { depth_cue(r_.rgbc, op); }

// DPCT: DPCS three times on the FIFO head RGB0 (which each push advances).
void Gte::dpct(Op op) {
  for (int k = 0; k < 3; ++k) depth_cue(r_.rgb[0], op);
}

// INTPL: [IR1..3] SHL 12 depth-cued towards FC.
void Gte::intpl(Op op) {
  interpolate_color(s64(r_.ir[1]) << 12, s64(r_.ir[2]) << 12, s64(r_.ir[3]) << 12, op);
  push_rgb_from_mac();
}

// DCPL: the NCDx tail on its own (RGBC times IR, depth-cued).
void Gte::dcpl(Op op) { depth_cue_color_times_ir(op); }

void Gte::ncs(Op op) {
  light_color(r_.v[0], op);
  push_rgb_from_mac();
}

void Gte::nct(Op op) {
  for (const Vec16& v : r_.v) {
    light_color(v, op);
    push_rgb_from_mac();
  }
}

void Gte::nccs(Op op) {
  light_color(r_.v[0], op);
  color_times_ir(op);
}

void Gte::ncct(Op op) {
  for (const Vec16& v : r_.v) {
    light_color(v, op);
    color_times_ir(op);
  }
}

void Gte::ncds(Op op) {
  light_color(r_.v[0], op);
  depth_cue_color_times_ir(op);
}

void Gte::ncdt(Op op) {
  for (const Vec16& v : r_.v) {
    light_color(v, op);
    depth_cue_color_times_ir(op);
  }
}

void Gte::cc(Op op) {
  color_ir(op);
  color_times_ir(op);
}

void Gte::cdp(Op op) {
  color_ir(op);
  depth_cue_color_times_ir(op);
}

}  // namespace psx
