// GTE register file: the read/write quirks of the 32 data and 32 control registers
// (psx-spx "GTE Data Register Summary", "GTE Control Register Summary"), command dispatch
// with the documented cycle counts, and save states.
#include "core/gte/gte.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <type_traits>

namespace psx {

namespace {

// VXY/SXY-style packing: low half X, high half Y.
u32 pack(s16 lo, s16 hi) { return u32(u16(lo)) | (u32(u16(hi)) << 16); }

// Control registers 0-4, 8-12, 16-20 hold a 3x3 matrix of s16 two per word, row-major;
// the fifth word holds only element 33 and reads sign-extended.
u32 read_matrix(const std::array<std::array<s16, 3>, 3>& m, u32 k) {
  const u32 i = 2 * k;
  if (k == 4) return u32(s32(m[2][2]));
  return pack(m[i / 3][i % 3], m[(i + 1) / 3][(i + 1) % 3]);
}

void write_matrix(std::array<std::array<s16, 3>, 3>& m, u32 k, u32 v) {
  const u32 i = 2 * k;
  m[i / 3][i % 3] = s16(v);
  if (k != 4) m[(i + 1) / 3][(i + 1) % 3] = s16(v >> 16);
}

// ORGB: each of IR1-IR3 divided by 80h and saturated to 0..1Fh (no flags).
u32 orgb_component(s16 ir) { return u32(std::clamp(ir >> 7, 0, 0x1F)); }

}  // namespace

u32 Gte::read_data(u32 r) {
  r &= 31;
  switch (r) {
    case 0: case 2: case 4: return pack(r_.v[r / 2][0], r_.v[r / 2][1]);
    case 1: case 3: case 5: return u32(s32(r_.v[r / 2][2]));
    case 6: return r_.rgbc;
    case 7: return r_.otz;
    case 8: case 9: case 10: case 11: return u32(s32(r_.ir[r - 8]));
    case 12: case 13: case 14: return r_.sxy[r - 12];
    case 15: return r_.sxy[2];  // SXYP reads as a mirror of SXY2
    case 16: case 17: case 18: case 19: return r_.sz[r - 16];
    case 20: case 21: case 22: return r_.rgb[r - 20];
    case 23: return r_.res1;
    case 24: case 25: case 26: case 27: return u32(r_.mac[r - 24]);
    case 28: case 29:  // IRGB reads as ORGB
      return orgb_component(r_.ir[1]) | (orgb_component(r_.ir[2]) << 5) | (orgb_component(r_.ir[3]) << 10);
    case 30: return r_.lzcs;
    default: return r_.lzcr;
  }
}

std::optional<Gte::Field> Gte::data_field(u32 r, bool write) {
  static_assert(std::is_standard_layout_v<Gte> && std::is_standard_layout_v<Registers>);
  // Byte `at` of the register file, `bytes` wide.
  const auto field = [](size_t at, u32 bytes, bool sign) { return Field{u32(offsetof(Gte, r_) + at), bytes, sign}; };
  constexpr size_t kVec = sizeof(Vec16), kS16 = sizeof(s16), kU32 = sizeof(u32);
  r &= 31;
  switch (r) {
    case 0: case 2: case 4: return field(offsetof(Registers, v) + r / 2 * kVec, 4, false);  // VXY: X low, Y high
    case 1: case 3: case 5: return field(offsetof(Registers, v) + r / 2 * kVec + 2 * kS16, 2, true);
    case 6: return field(offsetof(Registers, rgbc), 4, false);
    case 7: return field(offsetof(Registers, otz), 2, false);
    case 8: case 9: case 10: case 11: return field(offsetof(Registers, ir) + (r - 8) * kS16, 2, true);
    case 12: case 13: case 14: return field(offsetof(Registers, sxy) + (r - 12) * kU32, 4, false);
    case 15: return write ? std::nullopt : std::optional(field(offsetof(Registers, sxy) + 2 * kU32, 4, false));
    case 16: case 17: case 18: case 19: return field(offsetof(Registers, sz) + (r - 16) * sizeof(u16), 2, false);
    case 20: case 21: case 22: return field(offsetof(Registers, rgb) + (r - 20) * kU32, 4, false);
    case 23: return field(offsetof(Registers, res1), 4, false);
    case 24: case 25: case 26: case 27: return field(offsetof(Registers, mac) + (r - 24) * kU32, 4, false);
    case 30: return write ? std::nullopt : std::optional(field(offsetof(Registers, lzcs), 4, false));
    case 31: return write ? std::nullopt : std::optional(field(offsetof(Registers, lzcr), 4, false));
    default: return std::nullopt;  // IRGB, ORGB
  }
}

void Gte::write_data(u32 r, u32 v) {
  r &= 31;
  switch (r) {
    case 0: case 2: case 4:
      r_.v[r / 2][0] = s16(v);
      r_.v[r / 2][1] = s16(v >> 16);
      break;
    case 1: case 3: case 5: r_.v[r / 2][2] = s16(v); break;
    case 6: r_.rgbc = v; break;
    case 7: r_.otz = u16(v); break;
    case 8: case 9: case 10: case 11: r_.ir[r - 8] = s16(v); break;
    case 12: case 13: case 14: r_.sxy[r - 12] = v; break;
    case 15:  // SXYP: a write pushes the screen XY FIFO
      r_.sxy[0] = r_.sxy[1];
      r_.sxy[1] = r_.sxy[2];
      r_.sxy[2] = v;
      break;
    case 16: case 17: case 18: case 19: r_.sz[r - 16] = u16(v); break;
    case 20: case 21: case 22: r_.rgb[r - 20] = v; break;
    case 23: r_.res1 = v; break;
    case 24: case 25: case 26: case 27: r_.mac[r - 24] = s32(v); break;
    case 28:  // IRGB: 5-bit colours expanded into IR1-IR3 (times 80h)
      r_.ir[1] = s16((v & 0x1F) << 7);
      r_.ir[2] = s16(((v >> 5) & 0x1F) << 7);
      r_.ir[3] = s16(((v >> 10) & 0x1F) << 7);
      break;
    case 30:  // LZCS: LZCR counts its leading bits equal to bit 31 (1..32)
      r_.lzcs = v;
      r_.lzcr = u32(std::countl_zero(s32(v) < 0 ? ~v : v));
      break;
    default: break;  // ORGB and LZCR are read-only
  }
}

u32 Gte::read_control(u32 r) {
  r &= 31;
  switch (r) {
    case 0: case 1: case 2: case 3: case 4: return read_matrix(r_.rt, r);
    case 5: case 6: case 7: return u32(r_.tr[r - 5]);
    case 8: case 9: case 10: case 11: case 12: return read_matrix(r_.llm, r - 8);
    case 13: case 14: case 15: return u32(r_.bk[r - 13]);
    case 16: case 17: case 18: case 19: case 20: return read_matrix(r_.lcm, r - 16);
    case 21: case 22: case 23: return u32(r_.fc[r - 21]);
    case 24: return u32(r_.ofx);
    case 25: return u32(r_.ofy);
    case 26: return u32(s32(s16(r_.h)));  // H is unsigned but reads sign-extended
    case 27: return u32(s32(r_.dqa));
    case 28: return u32(r_.dqb);
    case 29: return u32(s32(r_.zsf3));
    case 30: return u32(s32(r_.zsf4));
    default: return r_.flag | ((r_.flag & kFlagErrorMask) ? kFlagError : 0);
  }
}

void Gte::write_control(u32 r, u32 v) {
  r &= 31;
  switch (r) {
    case 0: case 1: case 2: case 3: case 4: write_matrix(r_.rt, r, v); break;
    case 5: case 6: case 7: r_.tr[r - 5] = s32(v); break;
    case 8: case 9: case 10: case 11: case 12: write_matrix(r_.llm, r - 8, v); break;
    case 13: case 14: case 15: r_.bk[r - 13] = s32(v); break;
    case 16: case 17: case 18: case 19: case 20: write_matrix(r_.lcm, r - 16, v); break;
    case 21: case 22: case 23: r_.fc[r - 21] = s32(v); break;
    case 24: r_.ofx = s32(v); break;
    case 25: r_.ofy = s32(v); break;
    case 26: r_.h = u16(v); break;
    case 27: r_.dqa = s16(v); break;
    case 28: r_.dqb = s32(v); break;
    case 29: r_.zsf3 = s16(v); break;
    case 30: r_.zsf4 = s16(v); break;
    default: r_.flag = v & 0x7FFFF000; break;  // bits 0-11 read 0, bit 31 is computed
  }
}

u32 Gte::command_cycles(u32 command) {
  switch (command & 0x3F) {
    case 0x01: return 15;  // RTPS
    case 0x06: return 8;   // NCLIP
    case 0x0C: return 6;   // OP
    case 0x10: return 8;   // DPCS
    case 0x11: return 8;   // INTPL
    case 0x12: return 8;   // MVMVA
    case 0x13: return 19;  // NCDS
    case 0x14: return 13;  // CDP
    case 0x16: return 44;  // NCDT
    case 0x1B: return 17;  // NCCS
    case 0x1C: return 11;  // CC
    case 0x1E: return 14;  // NCS
    case 0x20: return 30;  // NCT
    case 0x28: return 5;   // SQR
    case 0x29: return 8;   // DCPL
    case 0x2A: return 17;  // DPCT
    case 0x2D: return 5;   // AVSZ3
    case 0x2E: return 6;   // AVSZ4
    case 0x30: return 23;  // RTPT
    case 0x3D: return 5;   // GPF
    case 0x3E: return 5;   // GPL
    case 0x3F: return 39;  // NCCT
    default: return 1;
  }
}

u32 Gte::execute(u32 command) {
  command_function(command)(*this, command);
  return command_cycles(command);
}

Gte::Op Gte::op_of(u32 command) { return {(command & (1u << 19)) ? 12u : 0u, (command & (1u << 10)) != 0}; }

template <void (Gte::*F)(Gte::Op)>
void Gte::run_op(Gte& g, u32 command) {
  g.r_.flag = 0;  // every command starts with a clear FLAG
  (g.*F)(op_of(command));
}

Gte::Command Gte::command_function(u32 command) {
  switch (command & 0x3F) {
    case 0x01: return &run_op<&Gte::rtps>;
    case 0x06: return [](Gte& g, u32) { g.r_.flag = 0, g.nclip(); };
    case 0x0C: return &run_op<&Gte::op_cross>;
    case 0x10: return &run_op<&Gte::dpcs>;
    case 0x11: return &run_op<&Gte::intpl>;
    case 0x12: return [](Gte& g, u32 c) { g.r_.flag = 0, g.mvmva(c, op_of(c)); };
    case 0x13: return &run_op<&Gte::ncds>;
    case 0x14: return &run_op<&Gte::cdp>;
    case 0x16: return &run_op<&Gte::ncdt>;
    case 0x1B: return &run_op<&Gte::nccs>;
    case 0x1C: return &run_op<&Gte::cc>;
    case 0x1E: return &run_op<&Gte::ncs>;
    case 0x20: return &run_op<&Gte::nct>;
    case 0x28: return &run_op<&Gte::sqr>;
    case 0x29: return &run_op<&Gte::dcpl>;
    case 0x2A: return &run_op<&Gte::dpct>;
    case 0x2D: return [](Gte& g, u32) { g.r_.flag = 0, g.avsz3(); };
    case 0x2E: return [](Gte& g, u32) { g.r_.flag = 0, g.avsz4(); };
    case 0x30: return &run_op<&Gte::rtpt>;
    case 0x3D: return &run_op<&Gte::gpf>;
    case 0x3E: return &run_op<&Gte::gpl>;
    case 0x3F: return &run_op<&Gte::ncct>;
    default: return [](Gte& g, u32) { g.r_.flag = 0; };  // opcodes psx-spx does not list compute nothing
  }
}

void Gte::do_state(StateIO& s) {
  // Field by field, so padding bytes never reach the state.
  s.section("GTE ", 2);
  s.pod(r_.v);
  s.pod(r_.rgbc);
  s.pod(r_.otz);
  s.pod(r_.ir);
  s.pod(r_.sxy);
  s.pod(r_.sz);
  s.pod(r_.rgb);
  s.pod(r_.res1);
  s.pod(r_.mac);
  s.pod(r_.lzcs);
  s.pod(r_.lzcr);
  s.pod(r_.rt);
  s.pod(r_.llm);
  s.pod(r_.lcm);
  s.pod(r_.tr);
  s.pod(r_.bk);
  s.pod(r_.fc);
  s.pod(r_.ofx);
  s.pod(r_.ofy);
  s.pod(r_.h);
  s.pod(r_.dqa);
  s.pod(r_.dqb);
  s.pod(r_.zsf3);
  s.pod(r_.zsf4);
  s.pod(r_.flag);
  s.end_section("GTE ");
}

}  // namespace psx
