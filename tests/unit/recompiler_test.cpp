// The differential test of the recompiler (core/cpu/recompiler/recompiler.h): the interpreter is
// the reference, and every program run under the recompiler must end in exactly the state it ends
// in under the interpreter, compared as whole save states (RAM, VRAM, CPU registers and pipeline,
// cycle counter, every device) plus cycle and instruction counts. The programs: every test
// program built in tests/roms, Tumble's title and a level with moves, the cdboot ROM booting
// Tumble's disc (BIOS-ROM code, a DMA loading code into RAM), code that rewrites itself, seeded
// random instruction streams (cached and uncached) that raise exceptions of every kind, and
// streams dense in the ALU operations the recompiler emits as native code, mixed with loads into
// the same few registers (load delay slots, the load shadow, r0 as a target).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "core/console.h"
#include "recompiler_test_util.h"
#include "sanitizer_scale.h"
#include "tumble_console_util.h"

namespace {

using psx::Console;
using psx::u32;
using namespace recompiler_test;

void expect_same(const std::function<void(Console&)>& boot, const std::function<void(Console&)>& play,
                 bool idle_skip = true) {
  Console ref, rec;
  ref.set_idle_skip(idle_skip);
  rec.set_idle_skip(idle_skip);
  rec.set_cpu_mode(Console::CpuMode::Recompiler);
  ASSERT_EQ(rec.cpu_mode(), Console::CpuMode::Recompiler);
  boot(ref);
  boot(rec);
  play(ref);
  play(rec);
  EXPECT_EQ(ref.cycles(), rec.cycles());
  EXPECT_EQ(ref.instructions(), rec.instructions());
  EXPECT_TRUE(ref.save_state(false) == rec.save_state(false)) << "state differs under the recompiler";
  // Idle skipping's choices too: the recompiler hands loop heads to it (or passes one that is
  // backing off itself) exactly where the interpreter does.
  EXPECT_EQ(ref.idle_skip_stats().examinations, rec.idle_skip_stats().examinations);
  EXPECT_EQ(ref.idle_skip_stats().skips, rec.idle_skip_stats().skips);
  EXPECT_EQ(ref.idle_skip_stats().iterations, rec.idle_skip_stats().iterations);
  EXPECT_EQ(ref.idle_skip_stats().proofs, rec.idle_skip_stats().proofs);
  EXPECT_GT(rec.recompiler_stats().compiled, 0u);
  EXPECT_EQ(ref.recompiler_stats().compiled, 0u);
}

// Runs `scenario` on a console without idle skipping (which would skip a test loop's iterations
// rather than run them) under the interpreter and then under the recompiler, `mode` being the
// CPU mode it runs in, and expects the same state (state_of()) from both.
void expect_same_state(const std::function<void(Console&, Console::CpuMode mode)>& scenario) {
  std::vector<std::vector<psx::u8>> states;
  for (const auto mode : {Console::CpuMode::Interpreter, Console::CpuMode::Recompiler}) {
    Console c;
    c.set_idle_skip(false);
    c.set_cpu_mode(mode);
    scenario(c, mode);
    states.push_back(state_of(c));
  }
  EXPECT_TRUE(states[0] == states[1]) << "state differs under the recompiler";
}

TEST(RecompilerPrograms, EveryTestRom) {
  std::vector<std::filesystem::path> exes;
  for (const auto& e : std::filesystem::directory_iterator(PSXRL_BUILD_DIR "/tests/roms"))
    if (e.path().extension() == ".exe") exes.push_back(e.path());
  std::sort(exes.begin(), exes.end());
  // tests/roms/*.cmake builds 34 programs; fewer means the build tree is incomplete.
  ASSERT_GE(exes.size(), 30u);
  for (const auto& exe : exes) {
    SCOPED_TRACE(exe.filename().string());
    expect_same([&](Console& c) { c.boot_exe(exe.string()); }, [](Console& c) { c.run_frames(90); });
  }
}

TEST(RecompilerPrograms, TumbleTitleWithoutIdleSkip) {
  expect_same([](Console& c) { c.boot_exe(TUMBLE_EXE); }, [](Console& c) { c.run_frames(120); }, false);
}

TEST(RecompilerPrograms, TumbleLevelWithMoves) {
  expect_same([](Console& c) { c.boot_exe(TUMBLE_EXE); }, tumble_test::play_level_one_moves);
}

TEST(RecompilerPrograms, CdbootRomBootsTumbleDisc) {
  expect_same(tumble_test::boot_disc_with_cdboot_rom, [](Console& c) { c.run_frames(300); });
}

// Uncached code (KSEG1) that rewrites an instruction ahead of itself: the recompiled block holding
// it was compiled with the old word, and the write drops it (code_pages.h).
TEST(RecompilerCode, SelfModifyingUncachedCode) {
  const u32 base = 0xA0010000;
  std::vector<u32> code = {
      itype(0x0F, 0, kT0, 0xA001),          // lui t0, 0xA001
      itype(0x09, kS1, kS1, 1),             // addiu s1, s1, 1      (index 1)
      itype(0x23, kT0, kT1, 4),             // lw t1, 4(t0)         the word at index 1
      kNop,
      itype(0x09, kT1, kT1, 1),             // addiu t1, t1, 1      (immediate 1 -> 2 -> 3 ...)
      itype(0x2B, kT0, kT1, 4),             // sw t1, 4(t0)
      j(base + 4), kNop};
  expect_same_code(code, base);
}

// Random instruction streams from a seeded generator: ALU, shifts, multiply/divide, loads and
// stores (aligned and not, so address errors too) around a data area, short forward branches,
// COP0 reads, GTE transfers and commands, and arbitrary words (reserved instructions, traps).
// s7 holds the data area's address and is never written; the stream ends by jumping back.
std::vector<u32> random_stream(u32 seed, u32 length) {
  std::mt19937 rng(seed);
  auto pick = [&](u32 n) { return u32(rng() % n); };
  auto reg = [&]() {  // a destination: any register but s7 (23)
    u32 r = pick(31) + 1;
    return r == 23 ? 8u : r;
  };
  std::vector<u32> code;
  for (u32 i = 0; i < length; ++i) {
    const u32 s = pick(32), t = pick(32), d = reg(), imm = rng() & 0xFFFF;
    switch (pick(16)) {
      case 0: code.push_back(itype(0x08 + pick(8), s, reg(), imm)); break;  // ADDI .. LUI
      case 1: case 2: {
        static constexpr u32 kFuncts[] = {0x00, 0x02, 0x03, 0x04, 0x06, 0x07, 0x20, 0x21, 0x22, 0x23,
                                          0x24, 0x25, 0x26, 0x27, 0x2A, 0x2B};
        code.push_back(rtype(kFuncts[pick(16)], s, t, d, pick(32)));
        break;
      }
      case 3: code.push_back(rtype(0x18 + pick(4), s, t, 0)); break;             // MULT, MULTU, DIV, DIVU
      case 4: code.push_back(rtype(0x10 + pick(4), s, 0, d)); break;             // MFHI, MTHI, MFLO, MTLO
      case 5: case 6: {  // loads around s7 (LB LH LWL LW LBU LHU LWR)
        const u32 off = pick(4) == 0 ? imm & 0x3FF : (imm & 0x3FC);
        code.push_back(itype(0x20 + pick(7), 23, reg(), off));
        break;
      }
      case 7: {  // stores around s7 (SB SH SWL SW; SWR)
        static constexpr u32 kStores[] = {0x28, 0x29, 0x2A, 0x2B, 0x2E};
        const u32 off = pick(4) == 0 ? imm & 0x3FF : (imm & 0x3FC);
        code.push_back(itype(kStores[pick(5)], 23, t, off));
        break;
      }
      case 8: {  // short forward branches: BcondZ, BEQ, BNE, BLEZ, BGTZ
        static constexpr u32 kBranches[] = {0x01, 0x04, 0x05, 0x06, 0x07};
        const u32 op = kBranches[pick(5)];
        code.push_back(itype(op, s, op == 0x01 ? (pick(2) ? 0x10 : 0) | pick(2) : t, 1 + pick(6)));
        break;
      }
      case 9: code.push_back(itype(0x10, 0, reg(), 0) | (pick(2) ? 12u : 13u) << 11); break;  // MFC0 sr/cause
      case 10: code.push_back(itype(0x12, pick(2) ? 4 : 0, pick(2) ? reg() : t, 0) | pick(32) << 11); break;  // MTC2/MFC2
      case 11: code.push_back(0x4A000000u | (rng() & 0x1FFFFFF)); break;          // a GTE command
      case 12: code.push_back(itype(pick(2) ? 0x32 : 0x3A, 23, pick(32), imm & 0x3FC)); break;  // LWC2/SWC2
      case 13: code.push_back(rng()); break;                                        // anything
      default: code.push_back(itype(0x09, s, d, imm)); break;                       // ADDIU
    }
  }
  return code;
}

TEST(RecompilerCode, RandomInstructionStreams) {
  // 700 instructions (2.8 KiB) fit the 4 KiB i-cache, so cached runs take the fast steps
  // (recompiler_ops.h) once the lines are filled.
  for (int seed = 1; seed <= test_scale::sized(16, 4); ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    for (u32 base : {0x80010000u, 0xA0010000u}) {
      std::vector<u32> code = random_stream(seed, 700);
      code.push_back(j(base));
      code.push_back(kNop);
      expect_same_code(code, base, 0x40000000 /* CU2: GTE on */, random_regs(seed), 2);
    }
  }
}

// A stream for the native ALU operations (block_emitter.h): their every encoding, with operands
// and destinations among r0, t0-t3 so that they keep meeting loads to the same registers: an ALU
// op in a load's delay slot writing the loaded register (the load loses) or reading it (the old
// value), reads in the load's shadow (a stall), r0 as a destination. Straight runs up to a whole
// block long, so that scheduler deadlines fall inside native segments.
std::vector<u32> alu_stream(u32 seed, u32 length) {
  std::mt19937 rng(seed);
  auto pick = [&](u32 n) { return u32(rng() % n); };
  auto reg = [&]() { return pick(5) == 0 ? 0u : kT0 + pick(4); };
  std::vector<u32> code;
  for (u32 i = 0; i < length; ++i) {
    const u32 s = reg(), t = reg(), d = reg(), imm = rng() & 0xFFFF;
    const u32 kind = pick(20);
    if (kind < 6) {  // ADDIU SLTI SLTIU ANDI ORI XORI LUI
      static constexpr u32 kOps[] = {0x09, 0x0A, 0x0B, 0x0C, 0x0D, 0x0E, 0x0F};
      code.push_back(itype(kOps[pick(7)], s, d, imm));
    } else if (kind < 14) {  // SLL SRL SRA SLLV SRLV SRAV ADDU SUBU AND OR XOR NOR SLT SLTU
      static constexpr u32 kFuncts[] = {0x00, 0x02, 0x03, 0x04, 0x06, 0x07, 0x21, 0x23,
                                        0x24, 0x25, 0x26, 0x27, 0x2A, 0x2B};
      code.push_back(rtype(kFuncts[pick(14)], s, t, d, pick(32)));
    } else if (kind < 18) {  // LW LB LH LBU (aligned) around s7
      static constexpr u32 kLoads[] = {0x23, 0x23, 0x20, 0x21, 0x24};
      const u32 op = kLoads[pick(5)];
      code.push_back(itype(op, 23, d, imm & (op == 0x23 ? 0x3FC : op == 0x21 ? 0x3FE : 0x3FF)));
    } else if (kind < 19) {  // SW around s7
      code.push_back(itype(0x2B, 23, t, imm & 0x3FC));
    } else {  // a short forward BEQ, BNE, BLEZ or BGTZ (its delay slot is the next instruction)
      code.push_back(itype(0x04 + pick(4), s, t, 1 + pick(4)));
    }
  }
  return code;
}

TEST(RecompilerCode, NativeAluStreams) {
  for (u32 seed = 1; seed <= 24; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::vector<u32> code = alu_stream(seed, 900);
    code.push_back(j(0x80010000));
    code.push_back(kNop);
    expect_same_code(code, 0x80010000, 0, random_regs(seed), 3);
  }
}

// Load delay and load shadow cases next to native ALU operations, each named, in one loop.
TEST(RecompilerCode, NativeAluAfterLoads) {
  const u32 base = 0x80010000, kT2 = 10;
  const auto lw = [](u32 rt, u32 off) { return itype(0x23, 23, rt, off); };
  const auto addu = [](u32 d, u32 s, u32 t) { return rtype(0x21, s, t, d); };
  // After each case t0-t2 are added into s0, so that every case's values reach the state (an
  // even number of xors of a wrong value, one per pass of the loop, would cancel).
  const std::vector<std::vector<u32>> cases = {
      {lw(kT0, 0), addu(kT0, kT1, kT1)},             // delay slot writes the loaded register: it keeps the ALU value
      {lw(kT0, 4), addu(kT1, kT0, kT0)},             // delay slot reads the old t0
      {lw(kT0, 8), kNop, addu(kT1, kT0, kT2)},       // a read in the shadow after the delay slot: stall
      {lw(kT0, 12), kNop, kNop, kNop, kNop, kNop, kNop, kNop, addu(kT1, kT0, kT0)},  // shadow over
      {lw(0, 16), addu(kT1, 0, kT0)},                // a load to r0, then r0 read
      {lw(kT0, 20), addu(0, kT0, kT1), addu(kT2, 0, kT0)},  // r0 as an ALU target in the delay slot
      {lw(kT0, 24), lw(kT1, 28), addu(kT2, kT0, kT1)},      // two loads in flight
  };
  constexpr u32 kS0 = 16;
  std::vector<u32> code;
  for (const auto& c : cases) {
    code.insert(code.end(), c.begin(), c.end());
    for (u32 r : {kT0, kT1, kT2}) code.push_back(rtype(0x21, kS0, r, kS0));  // addu s0, s0, r
  }
  code.insert(code.end(), {itype(0x09, kT0, kT0, 1), itype(0x2B, 23, kT0, 0),  // addiu t0, t0, 1; sw t0, 0(s7)
                           itype(0x2B, 23, kS0, 24),                          // sw s0, 24(s7)
                           j(base), itype(0x09, kS1, kS1, 1)});               // addiu s1 in the delay slot
  std::vector<u32> regs(31);
  for (u32 r = 0; r < 31; ++r) regs[r] = 0x01010101u * (r + 1);
  regs[22] = 0x80100000;
  expect_same_code(code, base, 0, regs, 3);
}

// Native branches and jumps (block_emitter.h): a backward loop (its loop head), BLEZ/BGTZ both
// ways, JAL/JR/JALR links, ALU ops and loads in their delay slots, a load into ra just before a
// JAL that writes it, and a jump-register target read in a load's delay slot.
TEST(RecompilerCode, NativeBranches) {
  const u32 base = 0x80010000, sub = base + 0x100, kT2 = 10, kT3 = 11, kT4 = 12, kT5 = 13, kRa = 31;
  const auto addiu = [](u32 t, u32 s, u32 imm) { return itype(0x09, s, t, imm); };
  const auto addu = [](u32 d, u32 s, u32 t) { return rtype(0x21, s, t, d); };
  const auto lw = [](u32 rt, u32 off) { return itype(0x23, 23, rt, off); };
  std::vector<u32> code = {
      addiu(kT0, 0, 5),                                  // 0: t0 = 5
      addiu(kT0, kT0, 0xFFFF),                           // 1: loop: t0 -= 1
      itype(0x07, kT0, 0, 0xFFFE),                       // 2: bgtz t0, loop
      addiu(kT1, kT1, 3),                                // 3: delay slot
      lw(kRa, 0),                                        // 4: a load into ra ...
      jal(sub),                                          // 5: ... that the link overwrites
      addu(kT2, kRa, 0),                                 // 6: delay slot reads ra (the link)
      addiu(kT4, 0, 0),                                  // 7: back here
      itype(0x0D, kT4, kT4, (sub + 0x20) & 0xFFFF),      // 8: ori t4 (low half of sub2)
      itype(0x0F, 0, kT5, (sub + 0x20) >> 16),           // 9: lui t5 (high half)
      rtype(0x25, kT4, kT5, kT4),                        // 10: or t4, t4, t5
      rtype(0x09, kT4, 0, kT5),                          // 11: jalr t5, t4
      addu(kT3, kT5, kT1),                               // 12: delay slot reads the link
      itype(0x06, kT0, 0, 2),                            // 13: blez t0, +2 (taken: t0 = 0)
      lw(kT3, 8),                                        // 14: a load in the delay slot
      addiu(kT1, kT1, 100),                              // 15: skipped
      itype(0x06, kT1, 0, 2),                            // 16: blez t1, +2 (not taken)
      addu(kT2, kT2, kT3),                               // 17: delay slot
      itype(0x2B, 23, kT2, 12),                          // 18: sw t2, 12(s7)
      itype(0x2B, 23, kT3, 16),                          // 19: sw t3, 16(s7)
      j(base),                                           // 20
      kNop};
  code.resize(0x40, kNop);
  const std::vector<u32> subroutine = {
      lw(kT3, 4), rtype(0x08, kRa, 0, 0), addu(kT3, kT3, kT1)};    // lw t3; jr ra; addu t3 (old t3)
  const std::vector<u32> sub2 = {
      lw(kT4, 0), rtype(0x08, kT5, 0, 0), addu(kT1, kT1, kT4)};   // jr t5 read in lw's delay slot
  code.insert(code.end(), subroutine.begin(), subroutine.end());
  code.resize(0x48, kNop);
  code.insert(code.end(), sub2.begin(), sub2.end());
  std::vector<u32> regs(31);
  for (u32 r = 0; r < 31; ++r) regs[r] = 0x01010101u * (r + 1);
  regs[22] = 0x80100000;
  expect_same_code(code, base, 0, regs, 3);
}

// Loops of one block that branch back to their own start, which a block runs again without
// leaving it or checking its guard a second time: a store through a moving pointer (never
// idle-skipped: it goes on looping past the loop head), a load in the delay slot read at the
// loop's first instruction (the load still pending there, then in its shadow), and a loop across
// an i-cache line boundary with a load read at once (a shadow stall) and stores.
TEST(RecompilerCode, LoopsOfOneBlock) {
  const u32 base = 0x80010000, kT2 = 10, kT3 = 11, kT4 = 12, kS7 = 23;
  const auto addiu = [](u32 t, u32 s, u32 imm) { return itype(0x09, s, t, imm); };
  const auto addu = [](u32 d, u32 s, u32 t) { return rtype(0x21, s, t, d); };
  const auto bgtz = [](u32 s, u32 off) { return itype(0x07, s, 0, off); };
  std::vector<u32> code = {
      addiu(kT2, 0, 200), addu(kT1, kS7, 0),                                  // 0
      itype(0x2B, kT1, 0, 0), addiu(kT2, kT2, 0xFFFF), bgtz(kT2, 0xFFFD),    // 2: sw zero, 0(t1)
      addiu(kT1, kT1, 4),                                                     // 5: delay slot
      addiu(kT2, 0, 300), addu(kT1, kS7, 0),                                  // 6
      addu(kT3, kT3, kT4), addiu(kT2, kT2, 0xFFFF), bgtz(kT2, 0xFFFD),       // 8: reads t4
      itype(0x23, kT1, kT4, 0),                                               // 11: lw t4, 0(t1)
      itype(0x2B, kS7, kT3, 4), addiu(kT2, 0, 100), kNop, kNop, kNop, kNop,   // 12
      itype(0x23, kS7, kT4, 8), addu(kT3, kT3, kT4),                          // 18: offset 8 of a line
      rtype(0x26, kT3, kT2, kT3), addiu(kT2, kT2, 0xFFFF), bgtz(kT2, 0xFFFB), // 20: xor t3, t3, t2
      itype(0x2B, kS7, kT3, 12),                                              // 23: sw t3, 12(s7)
      j(base), kNop};
  std::vector<u32> regs(31);
  for (u32 r = 0; r < 31; ++r) regs[r] = 0x01010101u * (r + 1);
  regs[kS7 - 1] = 0x80100000;
  expect_same_code(code, base, 0, regs, 3);
}

// A block goes on past a conditional branch that falls through, but not past one taken whatever
// the registers hold: GCC's `b` (BEQ r0, r0), BLEZ r0, `bal` (BGEZAL r0), BGEZ r0, a loop's last
// word with the loop's data right after it. A block that took those words for code would be
// dropped by every store to them: each loop stores there, and must run with its blocks compiled
// once (and the same results as the interpreter).
TEST(RecompilerCode, NoBlockGoesOnPastABranchAlwaysTaken) {
  const u32 base = 0x80010000, kT2 = 10;
  const u32 always[] = {itype(0x04, kT1, kT1, 0), itype(0x06, 0, 0, 0), itype(0x01, 0, 0x11, 0),
                        itype(0x01, 0, 0x01, 0)};  // BEQ t1, t1; BLEZ r0; BGEZAL r0; BGEZ r0
  for (u32 branch : always) {
    SCOPED_TRACE("branch " + std::to_string(branch >> 16));
    // loop: t2 += 1; sw t2, data(t0); ALWAYS loop; nop, then the data word the loop stores to.
    const std::vector<u32> code = {itype(0x09, kT2, kT2, 1), itype(0x2B, kT0, kT2, 16),
                                   branch | 0xFFFD, kNop, 0x24420001};  // back to the ADDIU
    const std::vector<u32> regs = {0, 0, 0, 0, 0, 0, 0, base};  // t0 (r8) = base
    expect_same_code(code, base, 0, regs, 2);
    Console c;
    c.set_cpu_mode(Console::CpuMode::Recompiler);
    load_code(c, code, base, 0, regs);
    c.run_frames(2);
    EXPECT_LE(c.recompiler_stats().invalidated, 1u);
  }
}

// The deadline stops a block wherever it falls and an interrupt returns to wherever it was
// taken; the CPU takes the program up there, inside the loop's compiled block, and runs to the
// loop's branch as the interpreter does rather than compiling a block from that point. A loop of
// 42 instructions runs for 12 frames; the events that stop it (frame ends, the SPU's samples and
// the others the scheduler books) fall at many points of it, so a block from each point would
// make many more than the loop's one block (and the handler's). The interrupt handler
// acknowledges VBlank, counts it in s1 and returns to EPC.
std::vector<u32> resume_loop() {
  std::vector<u32> code(40, itype(0x09, kT0, kT0, 1));          // addiu t0, t0, 1
  code.push_back(j(0x80010000));
  code.push_back(itype(0x09, kT1, kT1, 1));                      // addiu t1, t1, 1 (delay slot)
  return code;
}

TEST(RecompilerCode, ResumingInsideABlockCompilesNoBlockThere) {
  const u32 base = 0x80010000;
  expect_same_code(resume_loop(), base, 0, {}, 12);
  Console c;
  c.set_cpu_mode(Console::CpuMode::Recompiler);
  load_code(c, resume_loop(), base, 0, {});
  c.run_frames(12);
  EXPECT_EQ(c.recompiler_stats().compiled, 1u);
}

TEST(RecompilerCode, ReturningFromAnInterruptInsideABlockCompilesNoBlockThere) {
  const u32 base = 0x80010000, kK0 = 26, kK1 = 27;
  const auto vblank_irq = [](Console& c) {
    const std::vector<u32> handler = {itype(0x0F, 0, kK1, 0x1F80),          // lui k1, 1F80h
                                      itype(0x2B, kK1, 0, 0x1070),          // sw zero, I_STAT
                                      itype(0x09, kS1, kS1, 1),             // addiu s1, s1, 1
                                      itype(0x10, 0, kK0, 0) | 14 << 11,    // mfc0 k0, epc
                                      kNop, rtype(0x08, kK0, 0, 0),         // jr k0
                                      0x42000010};                          // rfe
    for (u32 i = 0; i < handler.size(); ++i) c.write32(0x80000080 + 4 * i, handler[i]);
    c.irq().write(4, 1);  // I_MASK (1F801074h): VBlank
  };
  const u32 sr = psx::Cop0::kIEc | 0x400;  // interrupts on, IM2 (the interrupt controller)
  expect_same_code(resume_loop(), base, sr, {}, 12, vblank_irq);
  Console c;
  c.set_cpu_mode(Console::CpuMode::Recompiler);
  load_code(c, resume_loop(), base, sr, {});
  vblank_irq(c);
  c.run_frames(12);
  EXPECT_GE(c.cpu().reg(kS1), 11u);  // a VBlank a frame
  EXPECT_EQ(c.recompiler_stats().compiled, 2u);  // the loop and the handler
}

// The same loop booted as an EXE under the HLE kernel, with timer 0 raising IRQ4 every 3001h
// cycles (mode 58h: reset and IRQ at the target, repeatedly; psx-spx "Timers"): the kernel's root
// counter handler acknowledges it and its ReturnFromException goes back into the loop's block.
TEST(RecompilerCode, HleReturnFromExceptionInsideABlockCompilesNoBlockThere) {
  const u32 base = 0x80010000, kT2 = 10;
  const auto li = [](u32 r, u32 v) { return itype(0x09, 0, r, v); };
  const auto sw = [](u32 r, u32 offset) { return itype(0x2B, kT2, r, offset); };  // sw r, offset(t2)
  std::vector<u32> code = {itype(0x0F, 0, kT2, 0x1F80),                  // lui t2, 1F80h
                           li(kT0, 0x3001), sw(kT0, 0x1108),             // timer 0 target
                           li(kT0, 0x58), sw(kT0, 0x1104),               // timer 0 mode
                           li(kT0, 0x10), sw(kT0, 0x1074),               // I_MASK: IRQ4
                           li(kT0, 0x0401), 0x40806000 | kT0 << 16};     // mtc0 t0, sr (IEc, IM2)
  const u32 loop = base + 4 * u32(code.size());
  code.insert(code.end(), 40, itype(0x09, kT1, kT1, 1));  // addiu t1, t1, 1
  code.push_back(j(loop));
  code.push_back(kNop);
  const u32 end = base + 4 * u32(code.size());
  std::vector<psx::u8> exe(0x800 + 0x800, 0);
  std::copy_n("PS-X EXE", 8, exe.begin());
  for (const auto& [at, v] : {std::pair<u32, u32>{0x10, base}, {0x18, base}, {0x1C, 0x800}, {0x30, 0x801FFF00}})
    psx::store_le32(&exe[at], v);
  for (u32 i = 0; i < code.size(); ++i) psx::store_le32(&exe[0x800 + 4 * i], code[i]);
  Console ref;
  ref.boot_exe_image(exe, "timer_loop.exe");
  ref.run_frames(12);
  Console c;
  c.set_cpu_mode(Console::CpuMode::Recompiler);
  c.boot_exe_image(exe, "timer_loop.exe");
  c.run_frames(12);
  EXPECT_TRUE(state_of(ref) == state_of(c)) << "state differs under the recompiler";
  EXPECT_GT(c.cpu().reg(kT1), 0u);
  const u32 epc = c.cpu().cop0().epc;  // the last interrupt was taken in the loop
  EXPECT_TRUE(epc >= loop && epc < end) << std::hex << epc;
  // The kernel's boot loop at 80000630h and its exit to the entry (hle_bios.h: kBootStub), the
  // program's entry, its loop, the vector at 80000080h.
  EXPECT_EQ(c.recompiler_stats().compiled, 5u);
}

// Cached code entered in the middle of i-cache lines: a miss fills from the fetched word to the
// line's end (psx-spx "Memory Map", i-Cache), so the loop's first line and the subroutine's
// line are held only in part, and their hits are as free as on whole lines (native code must
// still be the interpreter's timing). Every 64 passes the loop isolates the cache and writes its
// own line's tag with no valid bits (BCC.TAG, psx-spx "Memory Control" FFFE0130h), so the next
// pass misses and refills from the loop head.
TEST(RecompilerCode, PartlyValidICacheLines) {
  const u32 base = 0x80010000, kT2 = 10, kT3 = 11, kAt = 1, kCodeReg = 18;
  const auto addiu = [](u32 t, u32 s, u32 imm) { return itype(0x09, s, t, imm); };
  std::vector<u32> code(10, kNop);
  code[0] = j(base + 0x28);
  const std::vector<u32> loop = {
      addiu(kT0, kT0, 1),                                  // 0x28: loop (word 2 of its line)
      0x03u << 26 | (((base + 0x104) >> 2) & 0x03FFFFFF),  // jal sub (word 1 of its line)
      kNop,
      itype(0x0C, kT0, kT1, 63),                           // andi t1, t0, 63
      itype(0x05, kT1, 0, 13),                             // bne t1, zero, over the flush
      kNop,
      itype(0x0F, 0, kAt, 0xFFFE),                         // lui at, FFFEh
      itype(0x0F, 0, kT2, 1), itype(0x0D, kT2, kT2, 0xE98C),  // t2 = 1E98Ch: BCC with TAG
      itype(0x2B, kAt, kT2, 0x130),                        // sw t2, 130h(at)
      itype(0x0F, 0, kT3, 1), itype(0x10, 4, kT3, 0) | 12 << 11,  // mtc0 (SR.IsC), sr
      itype(0x2B, kCodeReg, 0, 0x28),                      // sw zero, 28h(code): the loop line's tag
      itype(0x10, 4, 0, 0) | 12 << 11,                     // mtc0 zero, sr
      itype(0x0D, 0, kT2, 0xE988), itype(0x0F, 0, kT3, 1), rtype(0x25, kT2, kT3, kT2),  // t2 = 1E988h
      itype(0x2B, kAt, kT2, 0x130),                        // BCC back to its reset value
      j(base + 0x28),                                      // over here: back to the loop
      addiu(kS1, kS1, 1)};
  code.insert(code.end(), loop.begin(), loop.end());
  code.resize(0x41, kNop);  // the subroutine at 0x104
  const std::vector<u32> sub = {rtype(0x21, kT3, kT0, kT3), rtype(0x08, 31, 0, 0), addiu(kT2, kT2, 3)};
  code.insert(code.end(), sub.begin(), sub.end());
  std::vector<u32> regs(31, 0);
  regs[kCodeReg - 1] = base;
  expect_same_code(code, base, 0, regs, 3);
}

// A jump to a misaligned address: the fetch there raises an address error (AdEL, Cause.ExcCode 4)
// with EPC and BadVaddr the address (psx-spx "COP0 - Exception Handling"). A compiled block's
// chain to the next block reads that pc; address 1 is also the empty mark of the recompiler's
// table of recent blocks, which a chain must not take for a block, with idle skipping off as on.
TEST(RecompilerCode, JumpToAMisalignedAddress) {
  const u32 base = 0x80010000;
  const std::vector<u32> code = {itype(0x0D, 0, kT0, 1), rtype(0x08, kT0, 0, 0), kNop};  // jr t0 (t0 = 1)
  for (bool idle_skip : {false, true}) {
    for (bool recompiler : {false, true}) {
      Console c;
      c.set_idle_skip(idle_skip);
      if (recompiler) c.set_cpu_mode(Console::CpuMode::Recompiler);
      for (u32 i = 0; i < code.size(); ++i) c.write32(base + 4 * i, code[i]);
      c.cpu().set_pc(base);
      c.run_frames(1);
      EXPECT_EQ((c.cpu().cop0().cause >> 2) & 0x1F, 4u) << "idle skip " << idle_skip << ", recompiler " << recompiler;
      EXPECT_EQ(c.cpu().cop0().epc, 1u);
      EXPECT_EQ(c.cpu().cop0().badvaddr, 1u);
    }
  }
}

// Cached code (KSEG0) that rewrites an instruction on a line further into its own block: psx-spx
// "Memory Map" (i-Cache) has stores bypass the cache, so the line, evicted each pass by a call to
// code with the same line index, is filled with the new word when the block reaches it. The
// block, compiled with the old word, is only dropped once it ends, so until then the written
// code's lines must not pass a native line check (ICache::kStale).
TEST(RecompilerCode, SelfModifyingCachedCodeFurtherInItsBlock) {
  const u32 base = 0x80010000, kS2 = 18, kS3 = 19, kRa = 31;
  std::vector<u32> code = {
      itype(0x0F, 0, kT0, 0x8001),                 // lui t0, 8001h
      itype(0x23, kT0, kT1, 0x24),                 // lw t1, 24h(t0): the word at index 9
      kNop,
      itype(0x09, kT1, kT1, 1),                    // addiu t1, t1, 1 (its immediate 1 -> 2 -> 3 ...)
      itype(0x2B, kT0, kT1, 0x24),                 // sw t1, 24h(t0)
      kNop, kNop, kNop,
      itype(0x09, kS1, kS1, 1),                    // line 2: addiu s1, s1, 1
      itype(0x09, kS2, kS2, 1),                    // addiu s2, s2, 1 (index 9, rewritten)
      itype(0x09, kS3, kS3, 1),                    // addiu s3, s3, 1
      kNop,
      0x03u << 26 | (((base + 0x1020) >> 2) & 0x03FFFFFF),  // jal base + 1020h (line 2 again)
      kNop,
      j(base), kNop};
  code.resize(0x408, kNop);
  code.push_back(rtype(0x08, kRa, 0, 0));  // base + 1020h: jr ra
  code.push_back(kNop);
  expect_same_code(code, base, 0, {}, 2);
}

// A state loaded over running code: the blocks compiled from the code before are not the code
// the state holds (its RAM and its i-cache lines differ from them), and must not run natively.
TEST(RecompilerCode, StateLoadedOverOtherCode) {
  const u32 base = 0x80010000, kS2 = 18;
  const auto program = [&](u32 step) {
    return std::vector<u32>{itype(0x09, kS1, kS1, 1), itype(0x09, kS2, kS2, step), itype(0x09, kS1, kS1, 1),
                            itype(0x09, kS2, kS2, step), kNop, kNop, j(base), kNop};
  };
  std::vector<psx::u8> other;
  {
    Console c;
    load_code(c, program(7), base, 0, {});
    c.run_frames(1);
    other = c.save_state(false);
  }
  expect_same_state([&](Console& c, Console::CpuMode) {
    load_code(c, program(1), base, 0, {});
    c.run_frames(1);
    c.load_state(other);
    c.run_frames(1);
  });
}

// A routine rewritten while the i-cache still holds it is compiled again from the cached old
// word, which must then run through calls (RecompilerT::compile()): once the line is refilled
// with the new word and no longer stale (after the next written code's recheck), a native copy
// of the old word would pass the line's check.
TEST(RecompilerCode, CodeRecompiledWhileTheICacheHoldsItsOldWord) {
  const u32 base = 0x80010000, kS2 = 18, kRa = 31;
  const u32 x = base + 0x100, y = base + 0x400, evict = base + 0x1100;  // x and evict share line 10h
  std::vector<u32> code = {
      itype(0x0F, 0, kT0, 0x8001),                                  // lui t0, 8001h
      jal(x), kNop,
      itype(0x23, kT0, kT1, 0x100), kNop, itype(0x09, kT1, kT1, 1),  // t1 = x's first word, immediate + 1
      itype(0x2B, kT0, kT1, 0x100),                                 // sw t1, 100h(t0): x rewritten
      jal(x), kNop,                                                 // compiled again, the old word cached
      jal(evict), kNop,                                             // the line evicted
      jal(x), kNop,                                                 // the new word filled
      jal(y), kNop,
      itype(0x2B, kT0, 0, 0x404),                                   // sw zero, 404h(t0): y's code written
      jal(x), kNop,
      j(base + 4), kNop};
  code.resize(0x40, kNop);
  code.insert(code.end(), {itype(0x09, kS2, kS2, 1), rtype(0x08, kRa, 0, 0), kNop});  // x: s2 += n
  code.resize(0x100, kNop);
  code.insert(code.end(), {rtype(0x08, kRa, 0, 0), kNop});  // y
  code.resize(0x440, kNop);
  code.insert(code.end(), {rtype(0x08, kRa, 0, 0), kNop});  // evict
  expect_same_state([&](Console& c, Console::CpuMode) {
    load_code(c, code, base, 0, {});
    c.run_frames(2);
  });
}

// A state whose i-cache holds older code than its RAM (code rewritten since it was cached),
// loaded where blocks were compiled from that RAM: the lines are stale, and the old words they
// hold keep running until evicted, as they did where the state was saved.
TEST(RecompilerCode, StateWithOlderCodeCachedThanInRam) {
  const u32 base = 0x80010000, kS2 = 18;
  const auto program = [&](u32 step) {
    return std::vector<u32>{itype(0x09, kS1, kS1, 1), itype(0x09, kS2, kS2, step), kNop, kNop, j(base), kNop};
  };
  std::vector<psx::u8> saved;
  {
    Console c;
    c.set_idle_skip(false);
    load_code(c, program(1), base, 0, {});
    c.run_frames(1);
    c.write32(base + 4, program(7)[1]);  // RAM now says 7; the cached line still says 1
    saved = c.save_state(false);
  }
  expect_same_state([&](Console& c, Console::CpuMode) {
    load_code(c, program(7), base, 0, {});
    c.run_frames(1);
    c.load_state(saved);
    c.run_frames(1);
  });
}

// Code rewritten while the interpreter runs (no code pages attached to see the write) and
// cached again from RAM: the blocks compiled before from the old code must not run when the
// recompiler takes over again, though the line's tag is the one they were compiled under.
TEST(RecompilerCode, CodeRewrittenWhileTheInterpreterRan) {
  const u32 base = 0x80010000, kS2 = 18, kRa = 31;
  std::vector<u32> code = {itype(0x09, kS1, kS1, 1), itype(0x09, kS2, kS2, 1),  // s2 += 1, then 7
                           jal(base + 0x1000), kNop, j(base), kNop};            // evicts base's line
  code.resize(0x400, kNop);
  code.insert(code.end(), {rtype(0x08, kRa, 0, 0), kNop});  // base + 1000h: the same line, returns
  expect_same_state([&](Console& c, Console::CpuMode mode) {
    load_code(c, code, base, 0, {});
    c.run_frames(1);
    c.set_cpu_mode(Console::CpuMode::Interpreter);
    c.write32(base + 4, itype(0x09, kS2, kS2, 7));
    c.run_frames(1);  // the line is refilled with the new word
    c.set_cpu_mode(mode);
    c.run_frames(1);
  });
}

// A BIOS image loaded over another while blocks compiled from the first are kept: the reset
// code goes through 9FC01100h, which evicts the cached loop's line (9FC00100h, KSEG0), so the
// loop is cached again from the new ROM, which no write reported.
TEST(RecompilerCode, BiosLoadedOverAnother) {
  const auto bios = [](u32 step) {
    constexpr u32 kS2 = 18;
    std::vector<psx::u8> image(psx::Bus::kBiosSize, 0);
    const auto put = [&](u32 off, std::vector<u32> words) {
      for (u32 w : words) psx::store_le32(&image[off], w), off += 4;
    };
    const auto go = [](u32 target) {  // lui t0; ori t0; jr t0; nop
      return std::vector<u32>{itype(0x0F, 0, kT0, target >> 16), itype(0x0D, kT0, kT0, target & 0xFFFF),
                              rtype(0x08, kT0, 0, 0), kNop};
    };
    put(0, go(0x9FC01100));
    put(0x1100, go(0x9FC00100));
    put(0x100, {itype(0x09, kS2, kS2, step), j(0x9FC00100), kNop});
    return image;
  };
  expect_same_state([&](Console& c, Console::CpuMode) {
    c.load_bios_image(bios(1), "one.bin");
    c.run_frames(1);
    c.load_bios_image(bios(7), "seven.bin");
    c.run_frames(1);
  });
}

}  // namespace
