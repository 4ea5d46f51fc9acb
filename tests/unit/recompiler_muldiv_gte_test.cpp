// The recompiler's native multiplies and divides (block_emitter_muldiv.cpp) and GTE instructions
// (block_emitter_cop2.cpp), differentially: every program must end in exactly the state (CPU
// registers, HI/LO, the multiply/divide unit's and the GTE's busy times, GTE registers, COP0,
// RAM, cycle and instruction counts) it ends in under the interpreter.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "core/cpu/cop0.h"
#include "recompiler_test_util.h"

namespace {

using namespace recompiler_test;

constexpr u32 kBase = 0x80010000;
constexpr u32 kT2 = 10, kT3 = 11, kS0 = 16, kS6 = 22, kS7 = 23;

// Operands where results and timing change: zero, one, -1, the most negative and most positive
// values (0x80000000 / -1 overflows), and the early-out multiplier's magnitude steps
// (psx-spx "CPU Timings": below 800h, below 100000h, the rest), both signs.
constexpr u32 kEdges[] = {0, 1, 0xFFFFFFFF, 0x80000000, 0x7FFFFFFF, 0x7FF, 0x800, 0xFFFFF,
                          0x100000, 0xFFFFF800, 0xFFFFF7FF, 0xFFF00000, 0xFFEFFFFF, 2, 0xFFFFFFFE};

// An edge value three times in four, else any.
u32 edge_or_random(std::mt19937& rng) { return rng() % 4 ? kEdges[rng() % std::size(kEdges)] : u32(rng()); }

// `length` instructions: t0-t3 set to edge values (LUI/ORI) or loaded (LW, so that operands are
// read in load delay slots and shadows), MULT/MULTU/DIV/DIVU on t0-t3 and r0, MFHI/MFLO right
// after or a few instructions later (the wait for the result, or none), MTHI/MTLO, the results
// added into s0 (added, not xored: the loop runs many times and xors would cancel), and short
// forward branches so that multiplies and divides meet delay slots.
std::vector<u32> muldiv_stream(u32 seed, u32 length) {
  std::mt19937 rng(seed);
  auto pick = [&](u32 n) { return u32(rng() % n); };
  auto reg = [&]() { return pick(8) == 0 ? 0u : kT0 + pick(4); };
  std::vector<u32> code;
  while (code.size() < length) {
    const u32 kind = pick(16);
    if (kind < 3) {
      const u32 v = edge_or_random(rng), d = kT0 + pick(4);
      code.push_back(itype(0x0F, 0, d, v >> 16));     // lui
      code.push_back(itype(0x0D, d, d, v & 0xFFFF));  // ori
    } else if (kind < 4) {
      code.push_back(itype(0x23, kS7, reg(), 4 * pick(256)));  // lw
    } else if (kind < 9) {
      code.push_back(rtype(0x18 + pick(4), reg(), reg(), 0));  // MULT MULTU DIV DIVU
    } else if (kind < 13) {
      const u32 d = reg();
      code.push_back(rtype(pick(2) ? 0x10 : 0x12, 0, 0, d));  // MFHI MFLO
      code.push_back(rtype(0x21, kS0, d, kS0));               // addu s0, s0, d
    } else if (kind < 14) {
      code.push_back(rtype(pick(2) ? 0x11 : 0x13, reg(), 0, 0));  // MTHI MTLO
    } else if (kind < 15) {
      code.push_back(itype(0x04 + pick(2), reg(), reg(), 1 + pick(3)));  // BEQ BNE
    } else {
      code.push_back(rtype(0x21, reg(), reg(), reg()));  // addu
    }
  }
  code.resize(length);
  code.push_back(itype(0x2B, kS7, kS0, 0x400));  // sw s0, 400h(s7)
  code.push_back(j(kBase));
  code.push_back(kNop);
  return code;
}

TEST(RecompilerMulDiv, RandomStreams) {
  for (u32 seed = 1; seed <= 16; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_code(muldiv_stream(seed, 700), kBase, 0, random_regs(seed), 2, [seed](Console& c) {
      std::mt19937 rng(seed);
      for (u32 a = 0; a < 0x400; a += 4) c.write32(0x80100000 + a, edge_or_random(rng));
    });
  }
}

// The GTE commands (psx-spx "GTE Command Summary"), by their low 6 bits.
constexpr u32 kGteOps[] = {0x01, 0x06, 0x0C, 0x10, 0x11, 0x12, 0x13, 0x14, 0x16, 0x1B, 0x1C,
                           0x1E, 0x20, 0x28, 0x29, 0x2A, 0x2D, 0x2E, 0x30, 0x3D, 0x3E, 0x3F};
constexpr u32 kCop2 = 0x12u << 26, kMfc2 = kCop2, kCfc2 = kCop2 | 2 << 21, kMtc2 = kCop2 | 4 << 21,
              kCtc2 = kCop2 | 6 << 21, kCommand = kCop2 | 1 << 25;

// `length` instructions: MTC2/CTC2 of t0-t3 (random values, loaded or set) into any GTE
// register, MFC2/CFC2 into t0-t3 and r0 (in the delay slot of a load to the same register or
// not, their value read in their own delay slot or later, added into s0), GTE commands with
// random sf/mx/v/cv/lm fields (an MFC2 right after one waits for it), LWC2/SWC2 to and from RAM
// and the scratchpad (misaligned now and then: an address error), loads, and SR writes
// that clear SR.CU2 now and then (the GTE instructions then raise Coprocessor Unusable, which
// the handler counts in s1 and skips). Branches have ALU delay slots, so an exception never
// returns into a delay slot.
std::vector<u32> gte_stream(u32 seed, u32 length) {
  std::mt19937 rng(seed);
  auto pick = [&](u32 n) { return u32(rng() % n); };
  auto reg = [&]() { return pick(8) == 0 ? 0u : kT0 + pick(4); };
  std::vector<u32> code;
  while (code.size() < length) {
    const u32 kind = pick(24);
    if (kind < 2) {
      const u32 v = u32(rng()), d = kT0 + pick(4);
      code.push_back(itype(0x0F, 0, d, v >> 16));     // lui
      code.push_back(itype(0x0D, d, d, v & 0xFFFF));  // ori
    } else if (kind < 5) {
      code.push_back(itype(0x23, kS7, reg(), 4 * pick(256)));  // lw
    } else if (kind < 10) {
      code.push_back((pick(2) ? kMtc2 : kCtc2) | reg() << 16 | pick(32) << 11);
    } else if (kind < 15) {
      const u32 d = reg();
      code.push_back((pick(3) ? kMfc2 : kCfc2) | d << 16 | pick(32) << 11);
      if (pick(2)) code.push_back(rtype(0x21, kS0, d, kS0));  // addu s0, s0, d (the old d)
      code.push_back(rtype(0x21, kS0, d, kS0));
    } else if (kind < 17) {  // LWC2/SWC2 through RAM or the scratchpad, misaligned one time in eight
      const u32 off = (4 * pick(256)) | (pick(8) == 0 ? 1 + pick(3) : 0);
      code.push_back(itype(pick(2) ? 0x32 : 0x3A, pick(2) ? kS7 : kS6, pick(32), off));
    } else if (kind < 19) {
      code.push_back(kCommand | (u32(rng()) & 0x1FFFFC0) | kGteOps[pick(std::size(kGteOps))]);
    } else if (kind < 20) {  // SR: COP2 usable three times in four
      code.push_back(itype(0x0F, 0, 1, pick(4) ? 0x4000 : 0));  // lui at
      code.push_back(itype(0x10, 4, 1, 0) | 12 << 11);          // mtc0 at, sr
    } else if (kind < 21) {
      code.push_back(itype(0x04 + pick(2), reg(), reg(), 2));  // BEQ BNE over one
      code.push_back(rtype(0x21, reg(), reg(), reg()));        // addu in the delay slot
    } else {
      code.push_back(rtype(0x21, reg(), reg(), reg()));  // addu
    }
  }
  code.resize(length);
  code.push_back(itype(0x0F, 0, 1, 0x4000));       // lui at, 4000h (SR.CU2)
  code.push_back(itype(0x10, 4, 1, 0) | 12 << 11);  // mtc0 at, sr
  code.push_back(itype(0x2B, kS7, kS0, 0x400));     // sw s0, 400h(s7)
  code.push_back(j(kBase));
  code.push_back(kNop);
  return code;
}

TEST(RecompilerGte, RandomStreams) {
  for (u32 seed = 1; seed <= 16; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::vector<u32> regs = random_regs(seed);
    regs[kS6 - 1] = 0x1F800000;  // the scratchpad
    expect_same_code(gte_stream(seed, 700), kBase, psx::Cop0::kCU2, regs, 2, [seed](Console& c) {
      std::mt19937 rng(seed);
      for (u32 a = 0; a < 0x400; a += 4) {
        c.write32(0x80100000 + a, u32(rng()));
        c.write32(0x1F800000 + a, u32(rng()));
      }
    });
  }
}

}  // namespace
