// Helpers for the recompiler's differential tests (recompiler_test.cpp, recompiler_memory_test.cpp):
// MIPS I encodings, and running a piece of code on a console without a BIOS under the
// interpreter and under the recompiler to compare the whole machine state afterwards.
#pragma once
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <vector>

#include "core/console.h"

namespace recompiler_test {

using psx::Console;
using psx::u32;

// MIPS I encodings (psx-spx "CPU Opcode Encoding"); registers by number.
constexpr u32 kT0 = 8, kT1 = 9, kS1 = 17;
inline u32 itype(u32 op, u32 rs, u32 rt, u32 imm) { return op << 26 | rs << 21 | rt << 16 | (imm & 0xFFFF); }
inline u32 rtype(u32 funct, u32 rs, u32 rt, u32 rd, u32 sa = 0) { return rs << 21 | rt << 16 | rd << 11 | sa << 6 | funct; }
inline u32 j(u32 target) { return 0x02u << 26 | ((target >> 2) & 0x03FFFFFF); }
inline u32 jal(u32 target) { return 0x03u << 26 | ((target >> 2) & 0x03FFFFFF); }
constexpr u32 kNop = 0;

// Loads `code` at `base` on a console without a BIOS, with an exception handler at 0x80000080
// (SR.BEV clear) that counts exceptions in s1 and returns past the instruction, registers r1..
// from `regs`, SR as given, and the CPU at `base`.
inline void load_code(Console& c, const std::vector<u32>& code, u32 base, u32 sr, const std::vector<u32>& regs) {
  for (u32 i = 0; i < code.size(); ++i) c.write32(base + 4 * i, code[i]);
  const std::vector<u32> handler = {itype(0x10, 0, 26, 0) | 14 << 11,  // mfc0 k0, epc
                                    kNop, itype(0x09, 26, 26, 4),       // addiu k0, k0, 4
                                    itype(0x09, kS1, kS1, 1),          // addiu s1, s1, 1
                                    rtype(0x08, 26, 0, 0),             // jr k0
                                    0x42000010};                       // rfe (in the delay slot)
  for (u32 i = 0; i < handler.size(); ++i) c.write32(0x80000080 + 4 * i, handler[i]);
  for (u32 r = 1; r < 32 && r <= regs.size(); ++r) c.cpu().set_reg(r, regs[r - 1]);
  c.cpu().cop0().sr = sr;
  c.cpu().set_pc(base);
}

// The console's save state with its cycle and instruction counts appended.
inline std::vector<psx::u8> state_of(Console& c) {
  std::vector<psx::u8> out = c.save_state(false);
  for (psx::u64 v : {psx::u64(c.cycles()), c.instructions()})
    for (int b = 0; b < 8; ++b) out.push_back(psx::u8(v >> (8 * b)));
  return out;
}

// Runs `code` (load_code) for `frames` frames under the given CPU; returns state_of().
// `setup`, when given, runs after load_code (to fill data areas, say).
inline std::vector<psx::u8> run_code(const std::vector<u32>& code, u32 base, u32 sr, const std::vector<u32>& regs,
                                     bool recompiled, int frames, const std::function<void(Console&)>& setup = {}) {
  Console c;
  if (recompiled) c.set_cpu_mode(Console::CpuMode::Recompiler);
  load_code(c, code, base, sr, regs);
  if (setup) setup(c);
  c.run_frames(frames);
  return state_of(c);
}

inline void expect_same_code(const std::vector<u32>& code, u32 base, u32 sr = 0, const std::vector<u32>& regs = {},
                             int frames = 4, const std::function<void(Console&)>& setup = {}) {
  EXPECT_TRUE(run_code(code, base, sr, regs, false, frames, setup) == run_code(code, base, sr, regs, true, frames, setup))
      << "state differs under the recompiler";
}

// Random register values (a third of them small), s7 (r23) pointing at the data area 0x80100000.
inline std::vector<u32> random_regs(u32 seed) {
  std::mt19937 rng(seed ^ 0x9E3779B9u);
  std::vector<u32> regs(31);
  for (u32& r : regs) r = rng() % 3 == 0 ? rng() % 64 : u32(rng());
  regs[22] = 0x80100000;  // s7: the data area
  return regs;
}

}  // namespace recompiler_test
