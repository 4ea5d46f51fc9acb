// The recompiler's time and position keeping, differentially: native code holds the scheduler's
// time, its deadline and the instruction count in host registers and writes the pc, next_pc and
// current_pc only where something outside the block can look (block_emitter.cpp). A probe event
// booked every few cycles makes the CPU return to the dispatcher in the middle of native
// segments, and at every return the CPU's whole saved state (registers, pc, next_pc, current_pc,
// delay-slot flags, load delay and shadow, instruction count) and the time must be what they are
// under the interpreter at the same return. The code reads a timer's counter (a call out that
// reads the time), writes a timer's target and mode (a call out that books an interrupt event
// a few cycles ahead, moving the deadline under the block's feet) and reads I_STAT (which shows
// whether that event ran on time), among native ALU operations,
// loads (the load shadow), multiplies and divides (their wait), GTE commands and transfers
// (calls out of native code) and branches.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "core/state.h"
#include "recompiler_test_util.h"
#include "sanitizer_scale.h"

namespace {

using namespace recompiler_test;
using psx::Cycles;
using psx::Scheduler;
using psx::u8;

constexpr u32 kBase = 0x80010000;
constexpr u32 kS5 = 21, kS6 = 22, kS7 = 23, kT3 = 11;
constexpr u32 kTimers = 0x1F801100, kIStat = 0x1F801070, kScratchpad = 0x1F800000;

// `length` instructions on t0-t3 and r0, with s5 = the timers, s6 = the scratchpad, s7 = RAM data.
std::vector<u32> timing_stream(u32 seed, u32 length) {
  std::mt19937 rng(seed);
  auto pick = [&](u32 n) { return u32(rng() % n); };
  auto reg = [&]() { return pick(6) == 0 ? 0u : kT0 + pick(4); };
  std::vector<u32> code;
  while (code.size() < length) {
    const u32 s = reg(), t = reg(), d = reg(), imm = rng() & 0xFFFF, kind = pick(24);
    if (kind < 6) {  // ADDIU SLTI SLTIU ANDI ORI XORI LUI
      code.push_back(itype(0x09 + pick(7), s, d, imm));
    } else if (kind < 10) {  // ADDU SUBU AND OR XOR NOR SLT SLTU, shifts
      static constexpr u32 kFuncts[] = {0x21, 0x23, 0x24, 0x25, 0x26, 0x27, 0x2A, 0x2B, 0x00, 0x04};
      code.push_back(rtype(kFuncts[pick(10)], s, t, d, pick(32)));
    } else if (kind < 13) {  // LW LB LHU from RAM (the load shadow) or LW from the scratchpad
      static constexpr u32 kLoads[] = {0x23, 0x20, 0x25};
      code.push_back(pick(4) == 0 ? itype(0x23, kS6, d, imm & 0x3FC) : itype(kLoads[pick(3)], kS7, d, imm & 0x3FC));
    } else if (kind < 14) {  // SW to RAM or the scratchpad
      code.push_back(itype(0x2B, pick(2) ? kS7 : kS6, t, imm & 0x3FC));
    } else if (kind < 15) {  // MULT MULTU DIV DIVU, MFHI MFLO (the wait for the result)
      code.push_back(pick(2) ? rtype(0x18 + pick(4), s, t, 0) : rtype(pick(2) ? 0x10 : 0x12, 0, 0, d));
    } else if (kind < 16) {  // a GTE command (RTPS, NCLIP, SQR, AVSZ3), MFC2/MTC2, LWC2 (waits, calls out)
      static constexpr u32 kGte[] = {0x4A180001, 0x4A280030, 0x4AA00428, 0x4B68002D};
      switch (pick(4)) {
        case 0: code.push_back(kGte[pick(4)]); break;
        case 1: code.push_back(itype(0x12, 0, d, 0) | pick(32) << 11); break;  // MFC2
        case 2: code.push_back(itype(0x12, 4, t, 0) | pick(32) << 11); break;  // MTC2
        default: code.push_back(itype(0x32, kS7, pick(32), imm & 0x3FC)); break;  // LWC2
      }
    } else if (kind < 17) {  // read timer 0's or timer 1's counter (the time, through a call)
      code.push_back(itype(0x23, kS5, d, pick(2) ? 0x00 : 0x10));
    } else if (kind < 18) {  // read I_STAT (has timer 0's IRQ come, exactly then?), or clear it
      code.push_back(pick(3) ? itype(0x23, kS5, d, kIStat - kTimers) : itype(0x2B, kS5, 0, kIStat - kTimers));
    } else if (kind < 19) {  // timer 0: a near target, then IRQ at target, repeat, reset there
      code.push_back(itype(0x0D, 0, kT3, 2 + pick(60)));
      code.push_back(itype(0x2B, kS5, kT3, 0x08));
      code.push_back(itype(0x0D, 0, kT3, 0x58));
      code.push_back(itype(0x2B, kS5, kT3, 0x04));
    } else if (kind < 22) {  // a short forward BEQ, BNE, BLEZ, BGTZ
      code.push_back(itype(0x04 + pick(4), s, t, 1 + pick(4)));
    } else if (kind < 23) {  // BLTZ, BGEZ, BLTZAL, BGEZAL forward
      code.push_back(itype(0x01, s, (pick(2) ? 0x10 : 0) | pick(2), 1 + pick(4)));
    } else {  // JAL a little forward, at most to the jump back
      const u32 to = std::min(u32(code.size()) + 2 + pick(4), length);
      code.push_back(j(kBase + 4 * to) | 1u << 26);
    }
  }
  code.resize(length);
  // Back to the start, three times over: a branch near the end may reach 5 words past it.
  for (int k = 0; k < 3; ++k) {
    code.push_back(j(kBase));
    code.push_back(kNop);
  }
  return code;
}

// The CPU's saved state and the time at every firing of a probe event that books itself again
// 1 to `gap` cycles later (kProbes times at most), over `frames` frames; the whole console's
// state_of() last. Every `irq_every`th firing (none where 0) also raises timer 0's IRQ, as the
// timer's own event would, wherever the CPU is then.
constexpr size_t kProbes = 20000;

std::vector<std::vector<u8>> probe_trace(const std::vector<u32>& code, u32 seed, bool recompiled, u32 gap, int frames,
                                         u32 irq_every = 0) {
  Console c;
  if (recompiled) c.set_cpu_mode(Console::CpuMode::Recompiler);
  std::vector<u32> regs = random_regs(seed);
  regs[kS5 - 1] = kTimers;
  regs[kS6 - 1] = kScratchpad;
  // CU2 (the GTE on), IEc and IM2: timer 0's IRQ interrupts the code where it comes, so that
  // running past a deadline the block should have seen shows as a later EPC.
  load_code(c, code, kBase, 0x40000401, regs);
  c.irq().write(4, 0x10);  // I_MASK: timer 0
  // The handler (the code raises no exceptions, so it only ever sees the interrupt): counts it
  // in s1, acknowledges every IRQ and returns to EPC.
  const std::vector<u32> handler = {itype(0x0F, 0, 27, 0x1F80), itype(0x2B, 27, 0, 0x1070),  // sw r0, I_STAT
                                    itype(0x10, 0, 26, 0) | 14 << 11, kNop,                    // mfc0 k0, epc
                                    itype(0x09, kS1, kS1, 1), rtype(0x08, 26, 0, 0), 0x42000010};
  for (u32 i = 0; i < handler.size(); ++i) c.write32(0x80000080 + 4 * i, handler[i]);
  std::mt19937 rng(seed * 31 + gap);
  for (u32 a = 0; a < 0x400; a += 4) c.write32(0x80100000 + a, u32(rng()));
  std::vector<std::vector<u8>> trace;
  Scheduler& sched = c.scheduler();
  Scheduler::Handle probe = -1;
  probe = sched.add_event("test.probe", [&](Cycles late) {
    psx::StateIO io;
    c.cpu().do_state(io);
    std::vector<u8> snap = io.buffer();
    for (psx::u64 v : {psx::u64(sched.now()), psx::u64(late)})
      for (int b = 0; b < 8; ++b) snap.push_back(u8(v >> (8 * b)));
    trace.push_back(std::move(snap));
    if (irq_every != 0 && trace.size() % irq_every == 0) c.irq().raise(psx::Irq::Timer0);
    if (trace.size() < kProbes) sched.schedule(probe, 1 + rng() % gap);
  });
  sched.schedule(probe, 1 + rng() % gap);
  c.run_frames(frames);
  trace.push_back(state_of(c));
  return trace;
}

void expect_same_trace(const std::vector<u32>& code, u32 seed, u32 gap, int frames, u32 irq_every = 0) {
  const auto ref = probe_trace(code, seed, false, gap, frames, irq_every);
  const auto rec = probe_trace(code, seed, true, gap, frames, irq_every);
  ASSERT_GT(ref.size(), 1000u);  // the probe keeps firing
  ASSERT_EQ(ref.size(), rec.size()) << "the probe fired a different number of times";
  for (size_t k = 0; k < ref.size(); ++k)
    ASSERT_TRUE(ref[k] == rec[k]) << "state differs at return " << k << " of " << ref.size();
}

TEST(RecompilerTiming, ProbedRandomStreams) {
  for (int seed = 1; seed <= test_scale::sized(10, 3); ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_trace(timing_stream(seed, 600), seed, 2 + seed * 7, 1);
  }
}

// The shadow after a load of the segment is that load's register or has ended (every load waits
// for the access before it), which native code takes as known (shadow_known()): a RAM load, then
// a scratchpad load, a store or another RAM load, then a divide read back by MFLO (its wait
// outlasts the access) or not, then one or two instructions reading the first load's register,
// the second's, both or neither, and the block's end, where the saved shadow shows whether the
// check cleared it and whether an instruction waited.
TEST(RecompilerTiming, ShadowAfterLoadsOfEveryKind) {
  constexpr u32 kT2 = 10;
  std::vector<u32> code;
  for (u32 second = 0; second < 3; ++second) {
    for (u32 use = 0; use < 4; ++use) {
      for (u32 wait = 0; wait < 2; ++wait) {
        code.push_back(itype(0x23, kS7, kT0, 4 * (second + use)));  // LW t0 from RAM
        switch (second) {
          case 0: code.push_back(itype(0x23, kS6, kT1, 8)); break;     // LW t1 from the scratchpad
          case 1: code.push_back(itype(0x2B, kS7, kT2, 0x100)); break;  // SW t2 to RAM
          default: code.push_back(itype(0x20, kS7, kT1, 0x40)); break;  // LB t1 from RAM
        }
        if (wait) code.push_back(rtype(0x1A, kT2, kT2, 0)), code.push_back(rtype(0x12, 0, 0, kT3));  // DIV, MFLO
        const u32 reads[4][2] = {{kT0, kT0}, {kT1, kT1}, {kT0, kT1}, {kT2, kT2}};
        for (u32 n = 0; n <= use % 2; ++n) code.push_back(rtype(0x21, reads[use][0], reads[use][1], kT2));
        code.push_back(j(kBase + 4 * (u32(code.size()) + 2)));  // on to the next block
        code.push_back(kNop);
      }
    }
  }
  code.push_back(j(kBase));
  code.push_back(kNop);
  for (u32 seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_trace(code, seed, 20 + 15 * seed, 2);
  }
}

// Straight ALU runs a whole block long, probed every 1 to 3 cycles: a return to the dispatcher
// after nearly every native instruction, at every position within a segment.
TEST(RecompilerTiming, ProbedEveryFewCycles) {
  std::vector<u32> code;
  std::mt19937 rng(7);
  for (u32 i = 0; i < 200; ++i) {
    const u32 s = kT0 + rng() % 4, d = kT0 + rng() % 4;
    code.push_back(i % 9 == 4 ? itype(0x23, kS7, d, (rng() % 256) * 4) : itype(0x09, s, d, rng() & 0xFFFF));
  }
  code.push_back(j(kBase));
  code.push_back(kNop);
  expect_same_trace(code, 3, 3, 1);
}

// Blocks go on past conditional branches that fall through (BlockEmitter::goes_on()): runs of a
// load, a short forward branch (never, always or about half the time taken) with an ALU delay
// slot at no line's start (the load before it leaves no stall to check), and an ALU operation,
// so that blocks reach kMaxBlock with branches split inside them, probed at
// gaps shorter and longer than a block (a return inside a segment, or where a chain finds the
// deadline reached): the position and delay-slot flags after a branch that fell through, at
// every return.
TEST(RecompilerTiming, ProbedBranchesFallingThrough) {
  std::vector<u32> code;
  std::mt19937 rng(11);
  for (u32 i = 0; i < 240; i += 4) {
    const u32 s = kT0 + rng() % 4, d = kT0 + rng() % 4;
    code.push_back(itype(0x23, kS7, d, (rng() % 256) * 4));  // LW
    switch (rng() % 4) {  // to the ADDU (where it falls through too) or past it
      case 0: code.push_back(itype(0x05, 0, 0, 1 + rng() % 2)); break;  // BNE r0, r0: never taken
      case 1: code.push_back(itype(0x04, 0, 0, 1 + rng() % 2)); break;  // BEQ r0, r0: always
      case 2: code.push_back(itype(0x07, s, 0, 1 + rng() % 2)); break;  // BGTZ s
      default: code.push_back(itype(0x01, s, 0, 1 + rng() % 2)); break;  // BLTZ s
    }
    code.push_back(itype(0x09, s, kT0 + rng() % 4, rng() & 0xFF));  // ADDIU (the delay slot)
    code.push_back(rtype(0x21, s, d, kT0 + rng() % 4));             // ADDU
  }
  code.push_back(j(kBase));
  code.push_back(kNop);
  for (u32 gap : {3u, 17u, 60u, 150u}) {
    SCOPED_TRACE("gap " + std::to_string(gap));
    expect_same_trace(code, gap, gap, 1);
  }
}

// Native code checks the deadline once per segment, against a bound on the cycles the segment's
// instructions can take (BlockEmitter's budget_check): each load's issue and bus access, each
// multiply's, divide's and GTE command's duration, the fill of each line, and the wait for a
// load, a divide or a GTE command still under way when the segment starts. A bound that left
// one of them out would let a segment run past a deadline that falls inside it. Loops of native
// code only (back-to-back loads, loads to the same register, divides then MFLO, NCDT and NCCT
// then MFC2, LWC2/SWC2, unaligned loads), longer than the 4 KiB i-cache so every pass refills
// its lines, probed at random gaps up to about one pass of a block.
std::vector<u32> budget_stream(u32 seed) {
  std::mt19937 rng(seed);
  auto pick = [&](u32 n) { return u32(rng() % n); };
  auto reg = [&]() { return kT0 + pick(4); };
  std::vector<u32> code;
  while (code.size() < 1200) {
    const u32 s = reg(), t = reg(), d = reg(), off = (rng() & 0x3FF) & ~3u, kind = pick(20);
    if (kind < 6) {  // LW LB LH LHU, often two in a row (the second waits for the bus)
      static constexpr u32 kLoads[] = {0x23, 0x20, 0x21, 0x25};
      code.push_back(itype(kLoads[pick(4)], kS7, d, off));
      if (pick(2)) code.push_back(itype(0x23, kS7, pick(2) ? d : t, off ^ 0x40));
    } else if (kind < 7) {  // LWL / LWR
      code.push_back(itype(pick(2) ? 0x22 : 0x26, kS7, d, off | pick(4)));
    } else if (kind < 9) {  // SW to RAM
      code.push_back(itype(0x2B, kS7, t, off));
    } else if (kind < 13) {  // ALU
      code.push_back(pick(2) ? itype(0x09, s, d, rng() & 0xFFFF) : rtype(0x21, s, t, d));
    } else if (kind < 15) {  // DIV DIVU MULT MULTU, then (maybe later) MFLO
      code.push_back(rtype(0x18 + pick(4), s, t, 0));
      if (pick(2)) code.push_back(rtype(0x12, 0, 0, d));
    } else if (kind < 16) {  // MFHI / MFLO on their own (a segment may start with the divide under way)
      code.push_back(rtype(pick(2) ? 0x10 : 0x12, 0, 0, d));
    } else if (kind < 18) {  // NCDT, NCCT, RTPT: 44, 39, 23 cycles; MFC2 waits for them
      static constexpr u32 kLong[] = {0x4AF80016, 0x4AF8003F, 0x4A280030};
      code.push_back(kLong[pick(3)]);
      if (pick(2)) code.push_back(itype(0x12, 0, d, 0) | (pick(32) << 11));  // MFC2
    } else {  // MFC2 (waits for a command under way), LWC2, SWC2
      switch (pick(3)) {
        case 0: code.push_back(itype(0x12, 0, d, 0) | (pick(32) << 11)); break;
        case 1: code.push_back(itype(0x32, kS7, pick(32), off)); break;
        default: code.push_back(itype(0x3A, kS7, pick(32), off)); break;
      }
    }
  }
  code.push_back(j(kBase));
  code.push_back(kNop);
  return code;
}

TEST(RecompilerTiming, ProbedNativeRuns) {
  for (int seed = 1; seed <= test_scale::sized(6, 2); ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_trace(budget_stream(seed), seed, 40 + 30 * seed, 1);
  }
}

// Blocks that branch back to their own start run pass after pass without their guard, checking
// the deadline's budget where they branch back. Their bodies make the bound nearly tight, so that
// a bound short of any one term shows: back-to-back loads (each waits for the last one's bus),
// LWC2s after an NCDT left under way by the previous pass, or MULTs of a large value each read
// back by MFLO after a divide left under way. t4 counts the passes down in the delay slot, and
// each pass stores it (an idle loop would be skipped, not run).
std::vector<u32> loop_stream(u32 seed) {
  constexpr u32 kT4 = 12;
  std::mt19937 rng(seed);
  auto pick = [&](u32 n) { return u32(rng() % n); };
  auto reg = [&]() { return kT0 + pick(4); };
  std::vector<u32> code;
  for (int unit = 0; unit < 9; ++unit) {
    code.push_back(itype(0x0D, 0, kT4, 20 + pick(20)));  // ori t4, r0, passes
    const size_t start = code.size();
    code.push_back(itype(0x2B, kS7, kT4, 0x400 + 4 * u32(unit)));  // sw t4: not an idle loop
    const u32 shape = pick(3), length = shape == 2 ? 4 + pick(10) : 8 + pick(14);  // at most 32 a block
    for (u32 k = 0; k < length; ++k) {
      const u32 off = (rng() & 0x3FF) & ~3u;
      if (shape == 0) {
        code.push_back(itype(0x23, kS7, reg(), off));  // LW
      } else if (shape == 1) {
        code.push_back(itype(0x32, kS7, pick(32), off));  // LWC2
      } else {
        code.push_back(rtype(0x12, 0, 0, kT1));                                // MFLO
        if (k == 0) code.push_back(itype(0x0F, 0, kT0, 0x7000 + pick(0x1000)));  // lui t0: a large rs
        code.push_back(rtype(0x18 + pick(2), kT0, reg(), 0));                  // MULT / MULTU
      }
    }
    code.push_back(shape == 1 ? 0x4AF80016 : rtype(0x1A, reg(), reg(), 0));  // NCDT / DIV
    const u32 back = u32(start) - u32(code.size() + 1);
    code.push_back(itype(0x05, kT4, 0, back));      // bne t4, r0, start
    code.push_back(itype(0x09, kT4, kT4, 0xFFFF));  // addiu t4, t4, -1
  }
  code.push_back(j(kBase));
  code.push_back(kNop);
  return code;
}

// A native run that reaches an i-cache line it cannot fill itself: BCC's IBLKSZ cleared (psx-spx
// "Memory Control" FFFE0130h; reset value 1E988h) makes a miss at a line's first word fill only two
// words, which the native fill refuses. Block A (14 instructions over four lines) and block B
// (one line) alternate, and B's line has the index of A's second line (4 KiB apart), so every pass
// of A hits its first line and misses its second there: A's native run leaves at that line's
// first instruction for its call, after four ALU instructions whose cycles it has counted only in
// the emitter (Impl::owed), and resumes natively two lines on. The probe compares the time too.
TEST(RecompilerTiming, LineMissesInsideNativeRuns) {
  constexpr u32 kA = 0x100, kB = kA + 0x1000 + 0x10, kAt = 1, kT2 = 10;
  std::vector<u32> code = {itype(0x0F, 0, kAt, 0xFFFE), itype(0x0F, 0, kT2, 1),  // lui at; lui t2, 1
                           itype(0x0D, kT2, kT2, 0xE888),                       // ori t2: 1E888h
                           itype(0x2B, kAt, kT2, 0x130),                        // sw t2, BCC
                           j(kBase + kA), kNop};
  code.resize(kA / 4, kNop);
  std::mt19937 rng(5);
  for (u32 i = 0; i < 12; ++i) code.push_back(itype(0x09, kT0 + rng() % 4, kT0 + rng() % 4, rng() & 0xFFFF));
  code.insert(code.end(), {j(kBase + kB), kNop});
  code.resize(kB / 4, kNop);
  code.insert(code.end(), {itype(0x09, kT0, kT1, 3), itype(0x09, kT2, kT0, 5), j(kBase + kA), kNop});
  for (u32 seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_trace(code, seed, 5 + 9 * seed, 1);
  }
}

// An I/O load's bus tail ends by the two instructions after it (CpuT::io_tail()); the native
// call knows them from the words compiled on the load's line, and on the next line while that
// line is whole in the i-cache (Impl::tail_plan(), call_io_load()). Polls of I_STAT at each word
// of a line, followed by a RAM load first, second or not at all, in a loop that every second
// pass runs code 4 KiB further on, which evicts every second line of the loop: there the next
// line misses, its fetch meets the tail first, and the call looks for itself.
TEST(RecompilerTiming, PortLoadTailsAcrossLines) {
  constexpr u32 kA = 0x100, kB = kA + 0x1000 + 0x10, kT2 = 10, kAt = 1;
  std::vector<u32> code = {itype(0x0F, 0, kAt, 0xFFFE), itype(0x0F, 0, kT2, 1),  // lui at; lui t2, 1
                           itype(0x0D, kT2, kT2, 0xE888),                       // ori t2: 1E888h
                           itype(0x2B, kAt, kT2, 0x130),                        // sw t2, BCC
                           j(kBase + kA), kNop};
  code.resize(kA / 4, kNop);
  for (u32 reach = 1; reach <= 3; ++reach) {
    for (u32 word = 0; word < 4; ++word) {
      while (code.size() % 4 != word) code.push_back(rtype(0x21, kT1, kT2, kT2));  // addu t2, t1, t2
      code.push_back(itype(0x23, kS5, kT0, kIStat - kTimers));                     // lw t0, I_STAT
      for (u32 n = 1; n < 3; ++n)
        code.push_back(n == reach ? itype(0x23, kS7, kT1, 4 * word) : rtype(0x21, kT0, kT2, kT2));
    }
  }
  const u32 end = u32(code.size());
  code.insert(code.end(), {itype(0x09, kT3, kT3, 1), itype(0x0C, kT3, kT2, 1),  // addiu t3; andi t2, t3, 1
                           itype(0x04, kT2, 0, (kA / 4) - (end + 3)), kNop,     // beq t2, r0, the loop
                           j(kBase + kB), kNop});
  for (u32 line = kB; line < kB + 4 * (end - kA / 4) + 32; line += 32) {
    code.resize(line / 4, kNop);
    code.insert(code.end(), {j(kBase + line + 32), kNop});
  }
  code.back() = kNop;
  code[code.size() - 2] = j(kBase + kA);
  for (u32 seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_trace(code, seed, 5 + 9 * seed, 1);
  }
}

TEST(RecompilerTiming, ProbedNativeLoops) {
  for (int seed = 1; seed <= test_scale::sized(6, 2); ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_trace(loop_stream(seed), seed, 200 + 100 * seed, 1);
  }
}

// A RAM load, then a jump whose delay slot starts a line that misses the i-cache: its fill
// outlasts the load's access, so the delay slot's check clears the shadow, which native code
// leaves to the chain on the way out (shadow()). The jump's target, a block of its own whose line
// the delay slot's evicts (4 KiB apart) and back, starts with an ALU operation and a store to a
// timer register (a call). Probed so that the deadline falls between the delay slot and the
// target: the chain must not go on into the target's block, whose refusal at the deadline would
// leave before its first instruction's check, with the shadow still set.
TEST(RecompilerTiming, ProbedJumpAfterLoadToTheDeadline) {
  constexpr u32 kA = 0x100, kB = kA + 0x1000 + 0x10;
  std::vector<u32> code = {j(kBase + kA), kNop};
  code.resize(kA / 4, kNop);
  code.insert(code.end(), {itype(0x09, kT1, kT1, 1), itype(0x09, kT1, kT1, 1),  // addiu t1 twice
                           itype(0x23, kS7, kT0, 0x40), j(kBase + kB), kNop});   // lw t0; the nop at kA + 10h
  code.resize(kB / 4, kNop);
  code.insert(code.end(), {itype(0x0D, 0, kT3, 0x40), itype(0x2B, kS5, kT3, 0x18),  // li t3; sw t3, timer 1
                           rtype(0x21, kT0, kT1, kT1), j(kBase + kA), kNop});
  for (u32 seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_trace(code, seed, 10 + 7 * seed, 1);
  }
}

// Native I/O accesses (Impl::io_access(): a load from or store to a port the recompiler guessed
// makes its read or write through one call and goes on natively): polls of timer 0's counter,
// I_STAT, GPUSTAT, SPUSTAT and the CD-ROM's status through s5, each followed in its i-cache line
// by ALU operations reading the value (its load delay slot, then the value), a RAM load (the
// shadow) and now and then a store of a register in a RAM load's delay slot (the old value) to
// timer 1's target, with the timer writes that book timer 0's IRQ native too, while that IRQ,
// booked a few cycles ahead, falls due inside a read (the SPU's and the CD-ROM's ports take longer
// than the RAM load the deadline's budget reckons with, so Bus::catch_up() runs the event there:
// the interrupt is taken before the next instruction, and the time left may not cover the rest of
// the run) and the probe returns to the dispatcher around and inside the reads. Then loops that
// poll, each one block looping natively (chain()), waiting for the IRQ's bit in I_STAT with a
// countdown as a way out.
TEST(RecompilerTiming, ProbedIoPolls) {
  constexpr u32 kT2 = 10, kT4 = 12, kGpuStat = 0x1F801814, kSpuStat = 0x1F801DAE, kCdStatus = 0x1F801800;
  constexpr u32 kLw = 0x23, kLhu = 0x25, kLbu = 0x24;
  constexpr u32 kPorts[][2] = {{kLw, 0x00}, {kLw, kIStat - kTimers}, {kLw, kGpuStat - kTimers}, {kLw, 0x10},
                               {kLhu, kSpuStat - kTimers}, {kLbu, kCdStatus - kTimers}};
  std::mt19937 rng(11);
  std::vector<u32> code;
  const auto irq_soon = [&] {
    code.push_back(itype(0x0D, 0, kT3, 8 + rng() % 160));  // ori t3, r0, n: the target
    code.push_back(itype(0x2B, kS5, kT3, 0x08));
    code.push_back(itype(0x0D, 0, kT3, 0x18));  // one IRQ at the target, the counter reset there
    code.push_back(itype(0x2B, kS5, kT3, 0x04));
  };
  // Each piece a block of its own (an interrupt returns into the middle of one, which then runs
  // interpreted to its end: RecompilerT::step_resumed()).
  const auto next_block = [&] {
    code.push_back(j(kBase + 4 * (u32(code.size()) + 2)));
    code.push_back(kNop);
  };
  for (u32 unit = 0; unit < 32; ++unit) {
    irq_soon();
    next_block();
    for (u32 n = 0; n < 2 + rng() % 3; ++n) {
      if (rng() % 3 == 0) {  // a branch split inside the run, mostly falling through to the poll
        code.push_back(itype(0x04, kT1, kT2, 1));  // beq t1, t2, +1
        code.push_back(kNop);
      }
      const auto& port = kPorts[rng() % 6];
      code.push_back(itype(port[0], kS5, kT0, port[1]));               // lw t0, a port
      code.push_back(rtype(0x21, kT0, kT1, kT1));                      // addu t1, t0, t1: the old t0
      code.push_back(rtype(0x21, kT0, kT2, kT2));                      // addu t2, t0, t2
      if (rng() % 2) code.push_back(itype(0x23, kS7, kT0, (rng() % 256) * 4));  // lw t0 from RAM
      if (rng() % 3 == 0) {  // a store to a port of the register a RAM load is about to land in
        code.push_back(itype(0x23, kS7, kT3, (rng() % 256) * 4));  // lw t3 from RAM
        code.push_back(itype(rng() % 2 ? 0x2B : 0x29, kS5, kT3, 0x18));  // sw/sh t3, timer 1's target
      }
    }
    next_block();
    // SPUSTAT and SPUCNT back to back: the reads outrun the budget, so later ones cross the
    // deadline.
    irq_soon();
    next_block();
    for (u32 n = 0; n < 3 + rng() % 4; ++n)
      code.push_back(itype(kLhu, kS5, kT0 + n % 3, kSpuStat - kTimers - 4 * (rng() % 2)));
    code.push_back(rtype(0x21, kT0, kT1, kT2));  // addu t2, t0, t1
    next_block();
  }
  for (u32 unit = 0; unit < 8; ++unit) {
    irq_soon();
    code.push_back(itype(0x0D, 0, kT4, 8 + rng() % 40));  // ori t4, r0: the countdown
    next_block();
    const size_t start = code.size();
    code.push_back(itype(0x23, kS5, kT0, kIStat - kTimers));  // lw t0, I_STAT
    code.push_back(itype(0x09, kT4, kT4, 0xFFFF));            // addiu t4, t4, -1
    code.push_back(itype(0x0C, kT0, kT0, 0x10));              // andi t0, t0, 10h: timer 0
    code.push_back(rtype(0x21, kT0, kT4, kT1));               // addu t1, t0, t4: 0 goes on
    code.push_back(itype(0x05, kT1, 0, u32(start) - u32(code.size() + 1)));  // bne t1, r0, start
    code.push_back(kNop);
  }
  code.push_back(j(kBase));
  code.push_back(kNop);
  for (u32 seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_trace(code, seed, 3 + 11 * seed, 1);
    expect_same_trace(code, seed, 60 + 30 * seed, 1, 1);  // interrupts from the probe too
  }
}

}  // namespace
