// Idle-loop skipping (core/cpu/idle_skip.h) must be invisible: every program run with skipping
// on ends in exactly the state it ends in with skipping off (the interpreter is the reference),
// compared as whole save states (RAM, VRAM, CPU registers, cycle counter, every device). The
// hand-written loops check which loops are skipped (counters in RAM words included) and which
// must not be (stores to moving or I/O addresses, stored words read in part, timer counter
// reads); the programs check whole workloads: Tumble's title and a level, the cdboot ROM booting
// Tumble's disc, and test ROMs.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "core/console.h"
#include "core/cpu/register_line.h"
#include "tumble_console_util.h"

namespace {

using psx::u32;
using psx::u64;
using psx::Console;

// MIPS I encodings (psx-spx "CPU Opcode Encoding"); registers by number.
constexpr u32 kT0 = 8, kT1 = 9, kT2 = 10, kT3 = 11, kT4 = 12, kT5 = 13, kS0 = 16, kS1 = 17;
u32 itype(u32 op, u32 rs, u32 rt, u32 imm) { return op << 26 | rs << 21 | rt << 16 | (imm & 0xFFFF); }
u32 lui(u32 rt, u32 imm) { return itype(0x0F, 0, rt, imm); }
u32 ori(u32 rt, u32 rs, u32 imm) { return itype(0x0D, rs, rt, imm); }
u32 addiu(u32 rt, u32 rs, int imm) { return itype(0x09, rs, rt, u32(imm)); }
u32 andi(u32 rt, u32 rs, u32 imm) { return itype(0x0C, rs, rt, imm); }
u32 lw(u32 rt, int off, u32 base) { return itype(0x23, base, rt, u32(off)); }
u32 sw(u32 rt, int off, u32 base) { return itype(0x2B, base, rt, u32(off)); }
u32 lbu(u32 rt, int off, u32 base) { return itype(0x24, base, rt, u32(off)); }
u32 bne(u32 rs, u32 rt, int off) { return itype(0x05, rs, rt, u32(off)); }
u32 beq(u32 rs, u32 rt, int off) { return itype(0x04, rs, rt, u32(off)); }
u32 bgtz(u32 rs, int off) { return itype(0x07, rs, 0, u32(off)); }
u32 sltu(u32 rd, u32 rs, u32 rt) { return rs << 21 | rt << 16 | rd << 11 | 0x2B; }
u32 j(u32 target) { return 0x02u << 26 | ((target >> 2) & 0x03FFFFFF); }
constexpr u32 kNop = 0;

struct Outcome {
  std::vector<psx::u8> state;
  psx::IdleSkip::Stats stats;
  u32 s1;
};

// Runs `code` placed at `base` (interrupts off, no BIOS) for `frames` frames; the SPU batches
// its samples unless `spu_every_sample` (Spu::set_max_batch(1): an event at every sample).
Outcome run_code(const std::vector<u32>& code, u32 base, bool skip, bool spu_every_sample = false, int frames = 6) {
  Console c;
  c.set_idle_skip(skip);
  if (spu_every_sample) c.spu().set_max_batch(1);
  for (u32 i = 0; i < code.size(); ++i) c.write32(base + 4 * i, code[i]);
  c.cpu().set_pc(base);
  c.run_frames(frames);
  return {c.save_state(false), c.idle_skip_stats(), c.cpu().reg(kS1)};
}

// Both ways; returns the skipping run's outcome after checking the states are equal.
Outcome compare(const std::vector<u32>& code, u32 base = 0x80010000, bool spu_every_sample = false) {
  Outcome off = run_code(code, base, false, spu_every_sample);
  Outcome on = run_code(code, base, true, spu_every_sample);
  EXPECT_EQ(off.stats.skips, 0u);
  EXPECT_TRUE(on.state == off.state) << "state differs with idle skipping";
  EXPECT_EQ(on.s1, off.s1);
  return on;
}

// Tumble's hw_wait_vblank: poll I_STAT bit 0 with a bounded spin counter, then acknowledge it and
// count the frame in s1 (4 instructions to set up, the loop at index 4).
std::vector<u32> vblank_wait() {
  return {lui(kT0, 0x1F80), addiu(kT1, 0, 0), lui(kT3, 0x0002), ori(kT3, kT3, 0x49F0),  // 150000
          lw(kT2, 0x1070, kT0), kNop, andi(kT2, kT2, 1), bne(kT2, 0, 5), kNop,
          addiu(kT1, kT1, 1), sltu(kT4, kT1, kT3), bne(kT4, 0, -8), kNop,
          sw(0, 0x1070, kT0), addiu(kS1, kS1, 1), j(0x80010004), kNop};
}

TEST(IdleSkip, VBlankPollWithSpinCounterIsSkippedExactly) {
  Outcome on = compare(vblank_wait());
  EXPECT_GT(on.stats.skips, 0u);
  // One frame is 263 lines of 3413 video cycles, 564480 CPU cycles at 33.8688/53.693175 MHz; a
  // spin iteration costs at least 9 cycles (8 instructions, an I/O read of 3), so a frame has
  // far more than 10000 iterations to skip.
  EXPECT_GT(on.stats.iterations, 6u * 10000);
  EXPECT_GE(on.s1, 5u);
}

// At each VBlank the poll leaves its loop: the proven iteration no longer repeats, and the way out
// (the acknowledging store to I_STAT) refuses every examination. Only the 1st, 2nd, 4th, 8th...
// such visit to the head is examined, so by the third one met (of the eleven exits in 12 frames;
// an exit inside the iteration interpreted right after a skip meets no head) some go unexamined.
// The states stay those of running without skipping.
TEST(IdleSkip, LoopLeftEveryFrameIsExaminedLessOften) {
  const Outcome off = run_code(vblank_wait(), 0x80010000, false, false, 12);
  const Outcome on = run_code(vblank_wait(), 0x80010000, true, false, 12);
  EXPECT_TRUE(on.state == off.state);
  EXPECT_GE(on.s1, 11u);
  EXPECT_GT(on.stats.unexamined, 0u);
  EXPECT_GT(on.stats.skips, on.s1);
}

// Two loops that can never qualify (each stores to I_MASK) take turns, 100 iterations each,
// their heads 4 KiB apart (0x80010008, 0x80011008): s1 counts the rounds. Each head backs off
// on its own: examined at its 1st, 3rd, 7th, 15th... visit, then once in every 2^12 (IdleSkip::
// kMaxBackoff is 12), so over its 99 visits a round (the first iteration is entered from above)
// it is examined at most 13 + 99 * rounds / 4096 times. Sharing a backoff entry, as in a
// 1024-entry table, each would reset the other's every round and be examined 6 times a round
// (visits 1, 3, 7, 15, 31 and 63 of 99); with at most 2^8 visits between examinations, 99 *
// rounds / 256 times.
TEST(IdleSkip, LoopsFourKibApartBackOffApart) {
  const std::vector<u32> a = {lui(kT0, 0x1F80), addiu(kT1, 0, 100), sw(0, 0x1074, kT0), addiu(kT1, kT1, -1),
                              bgtz(kT1, -3), kNop, j(0x80011004), kNop};
  const std::vector<u32> b = {addiu(kT1, 0, 100), sw(0, 0x1074, kT0), addiu(kT1, kT1, -1), bgtz(kT1, -3), kNop,
                              addiu(kS1, kS1, 1), j(0x80010004), kNop};
  std::vector<u32> code(1025 + b.size(), kNop);  // B from 0x80011004 (word 1025) on
  std::copy(a.begin(), a.end(), code.begin());
  std::copy(b.begin(), b.end(), code.begin() + 1025);
  const Outcome on = compare(code);
  EXPECT_EQ(on.stats.skips, 0u);
  EXPECT_GT(on.s1, 1000u);
  EXPECT_LE(on.stats.examinations, 2 * (13 + 99 * u64{on.s1} / 4096));
}

// After the event that ends a skip (the SPU's sample event, every 768 cycles when it steps every
// sample, among others) the loop is recorded again from its spin counter further on; the proof
// made the first time covers it. Six frames of 564480 cycles hold over 4400 sample events, so
// thousands of skips, and the states are equal with and without skipping (compare()).
TEST(IdleSkip, SpinLoopReusesItsProofAfterEachEvent) {
  Outcome on = compare(vblank_wait(), 0x80010000, true);
  EXPECT_GT(on.stats.skips, 4400u);
  EXPECT_LT(on.stats.proofs * 100, on.stats.skips);
}

// A countdown whose exit is 100 iterations after a skip must stop there even when the skip reuses
// a proof made thousands of iterations earlier: the bound shrinks by the iterations since. The SPU
// books every sample, so that events end skips often enough to reuse the proofs.
TEST(IdleSkip, ReusedProofStillEndsACountdownOnTime) {
  std::vector<u32> code = {lui(kT0, 0x0003), ori(kT0, kT0, 0x0D40),  // 200000
                           addiu(kT0, kT0, -1), bne(kT0, 0, -2), kNop,
                           addiu(kS1, kS1, 1), lui(kT0, 0x0001), ori(kT0, kT0, 0x86A0),  // 100000
                           addiu(kT0, kT0, -1), bne(kT0, 0, -2), kNop,
                           addiu(kS1, kS1, 1), j(0x80010000), kNop};
  Outcome on = compare(code, 0x80010000, true);
  EXPECT_GT(on.stats.skips, 0u);
  EXPECT_LT(on.stats.proofs * 10, on.stats.skips);
  // Each round is 300000 iterations of 2 instructions and at least 3 cycles (1 + branch + nop
  // slot), 900000+ cycles: six frames (3.39 M cycles) end within the fourth round.
  EXPECT_GE(on.s1, 4u);
}

// The same loop entered again with another bound (t3, which the loop does not change) records
// the same iteration from the same counter value, but the old proof's bound no longer holds.
TEST(IdleSkip, LoopEnteredWithAnotherBoundIsProvenAgain) {
  // t1 counts up to t3 = 70001, 50001, 30001, ...; s1 counts the rounds.
  std::vector<u32> code = {lui(kT3, 1), ori(kT3, kT3, 0x1171), addiu(kT1, 0, 0),
                           addiu(kT1, kT1, 1), bne(kT1, kT3, -2), kNop,
                           addiu(kS1, kS1, 1), addiu(kT3, kT3, -20000), j(0x80010008), kNop};
  Outcome on = compare(code);
  EXPECT_GT(on.stats.skips, 0u);
  // 70001 + 50001 + 30001 + 10001 iterations of at least 3 cycles: 480012 cycles, within the
  // first frame (564480); the fifth bound, -9999, takes 2^32 - 9999 iterations.
  EXPECT_EQ(on.s1, 4u);
}

// After each event that ends a skip the loop is met again, further along its line; the proof made
// the first time shows the iteration about to start repeats, so it is skipped from the head
// without recording one (IdleSkip::repeat). Each VBlank the loop is entered anew with its spin
// counter at 0, before the proof's recorded start: the same path is proven again from there.
TEST(IdleSkip, IterationsAfterAnEventRepeatWithoutRecording) {
  Outcome on = compare(vblank_wait(), 0x80010000, true);
  EXPECT_GT(on.stats.skips, 4400u);
  EXPECT_GT(on.stats.repeats * 10, on.stats.skips * 9);
}

// What a repeat takes from the proof must be what the iteration does now. Each program below
// changes, between rounds of its loop, something that shapes the loop's iterations but not its
// registers or loads, so that only that check keeps a repeat from taking the old proof's steps
// or cycles (compare() then finds the states differ). The SPU books every sample, so that events
// end skips and repeats are tried; `s1` counts the rounds, and six frames hold 3.39 M cycles.
void expect_rounds_repeated_exactly(const std::vector<u32>& code, u32 base) {
  Outcome on = compare(code, base, true);
  EXPECT_GE(on.s1, 2u);
  EXPECT_GT(on.stats.repeats, 0u);
}

// The loop's own code, uncached so that the fetch sees each new word: the counter steps by 1 in
// one round and by 2 in the next, to 65536.
TEST(IdleSkip, RewrittenLoopIsNotRepeatedFromTheOldCode) {
  const u32 xori_t4 = itype(0x0E, kT4, kT4, 3);  // 1 <-> 2
  std::vector<u32> code = {lui(kT5, 0xA001), addiu(kT1, 0, 0), lui(kT3, 1),
                           addiu(kT1, kT1, 1), bne(kT1, kT3, -2), kNop,  // 3: the loop
                           addiu(kS1, kS1, 1), lw(kT4, 12, kT5), kNop, xori_t4, sw(kT4, 12, kT5),
                           j(0xA0010004), kNop};
  // Two rounds: 65536 + 32768 iterations of 3 uncached instructions (a 4-cycle fetch and 1 to
  // execute each), 1.5 M cycles.
  expect_rounds_repeated_exactly(code, 0xA0010000);
}

// The BIOS ROM's read delay (Memory Control, 1F801010h bits 4-7), which times the loop's load
// from the ROM: 3 in one round, 12 in the next. With COM_DELAY 00031125h and the 8-bit bus a
// word takes 7 + 3 * 6 = 25 cycles at delay 3 and 16 + 3 * 15 = 61 at delay 12 (psx-spx
// "Memory Control", memory_control.h), so two rounds of 16384 iterations (the load and two
// cached instructions) take under 1.6 M cycles.
TEST(IdleSkip, LoopIsNotRepeatedAfterItsLoadsDelayChanges) {
  const u32 xori_t5 = itype(0x0E, kT5, kT5, 0xF0);
  std::vector<u32> code = {lui(kT0, 0xBFC0), lui(kT2, 0x1F80), addiu(kT1, 0, 0), ori(kT3, 0, 0x4000),
                           lw(kT4, 0, kT0), addiu(kT1, kT1, 1), bne(kT1, kT3, -3), kNop,  // 4: the loop
                           addiu(kS1, kS1, 1), lw(kT5, 0x1010, kT2), kNop, xori_t5,
                           sw(kT5, 0x1010, kT2), j(0x80010008), kNop};
  expect_rounds_repeated_exactly(code, 0x80010000);
}

// The i-cache (cache control FFFE0130h bit 11): on in one round, off in the next, while the lines
// the loop filled stay valid. Two rounds of 16384 iterations of 3 instructions take under 0.4 M
// cycles even uncached (5 cycles an instruction).
TEST(IdleSkip, LoopIsNotRepeatedAfterTheICacheIsSwitched) {
  const u32 xori_t5 = itype(0x0E, kT5, kT5, 0x800);
  std::vector<u32> code = {lui(kT2, 0xFFFE), addiu(kT1, 0, 0), ori(kT3, 0, 0x4000),
                           addiu(kT1, kT1, 1), bne(kT1, kT3, -2), kNop,  // 3: the loop
                           addiu(kS1, kS1, 1), lw(kT5, 0x130, kT2), kNop, xori_t5, sw(kT5, 0x130, kT2),
                           j(0x80010004), kNop};
  expect_rounds_repeated_exactly(code, 0x80010000);
}

// Two countdowns taking turns, as a pad transfer's loops polling for each byte and for its
// acknowledgement do (Tumble's), re-examined after every SPU sample event. Between rounds each
// meets the other's proof last, and registers neither names have moved on (s1 counts the rounds,
// t3 toggles). B loads a RAM flag the rounds toggle, so it needs a proof for each value. Without
// reuse across turns every round makes two proofs (each loop's first examination meets the
// other's); with it a few serve all rounds.
TEST(IdleSkip, LoopsTakingTurnsReuseTheirProofs) {
  const u32 xori_t3 = itype(0x0E, kT3, kT3, 1);
  std::vector<u32> code = {lui(kT4, 0x8002),                                             // t4: the flag
                           addiu(kT0, 0, 3000), addiu(kT0, kT0, -1), bne(kT0, 0, -2), kNop,  // 1: A
                           addiu(kT1, 0, 3000),                                              // 5: B
                           lw(kT2, 0, kT4), addiu(kT1, kT1, -1), bne(kT1, 0, -3), kNop,
                           lw(kT3, 0, kT4), kNop, xori_t3, sw(kT3, 0, kT4),  // 10: the flag toggles
                           addiu(kS1, kS1, 1), j(0x80010004), kNop};
  Outcome on = compare(code, 0x80010000, true);
  // A round is 3000 iterations of A (3 cycles each at least) and 3000 of B (4): 21000 cycles and
  // more, so six frames (3.39 M cycles) hold at most 161 rounds; each round's loops are examined
  // several times (an event every 768 cycles).
  EXPECT_GE(on.s1, 20u);
  EXPECT_GT(on.stats.skips, 4 * on.s1);
  EXPECT_LT(on.stats.proofs * 10, on.s1);
}

TEST(IdleSkip, UncachedCodeIsSkippedExactly) {
  std::vector<u32> code = vblank_wait();
  code[15] = j(0xA0010004);
  EXPECT_GT(compare(code, 0xA0010000).stats.skips, 0u);
}

TEST(IdleSkip, CountdownDelayLoopIsSkippedToItsEnd) {
  // s1 counts completed delays of 200000 iterations; the exit test is t0 == 0 after a decrement.
  std::vector<u32> code = {lui(kT0, 0x0003), ori(kT0, kT0, 0x0D40),  // 200000
                           addiu(kT0, kT0, -1), bne(kT0, 0, -2), kNop,
                           addiu(kS1, kS1, 1), j(0x80010000), kNop};
  Outcome on = compare(code);
  EXPECT_GT(on.stats.skips, 0u);
  EXPECT_GE(on.s1, 1u);
}

// A skip that the proof's bound ends leaves the loop at the iteration the proof could not show
// to repeat, here its last; the recorded iteration's back branch has set the loop head, so the
// head is met again at once. That iteration is not examined: it would record the exit and fail
// at the MULT (which no skipped loop may hold). A round of 100 iterations of 3 instructions plus
// 5 takes at most 305 * 5 cycles (a fetch of 4 and 1 to execute, no faster code assumed), so six
// frames (3.39 M cycles) hold over 2000 rounds, each examined once to a skip; without the rule
// each round also fails one examination. Events that end a skip early add an examination that
// skips too.
TEST(IdleSkip, IterationAfterASkipToTheBoundIsNotExamined) {
  const u32 mult_t0 = kT0 << 21 | kT0 << 16 | 0x18;
  std::vector<u32> code = {addiu(kT0, 0, 100), addiu(kT0, kT0, -1), bne(kT0, 0, -2), kNop,
                           mult_t0, addiu(kS1, kS1, 1), j(0x80010000), kNop};
  Outcome on = compare(code);
  EXPECT_GT(on.s1, 2000u);
  EXPECT_GE(on.stats.skips, on.s1);
  EXPECT_LT(on.stats.examinations - on.stats.skips, on.s1 / 100);
}

TEST(IdleSkip, EqualityExitOnAnUpCounterIsHonoured) {
  // Count t1 up to t3 = 70001 by 1 (BNE), then down by 3 while positive (BGTZ).
  std::vector<u32> code = {addiu(kT1, 0, 0), lui(kT3, 1), ori(kT3, kT3, 0x1171),
                           addiu(kT1, kT1, 1), bne(kT1, kT3, -2), kNop,
                           addiu(kT1, kT1, -3), bgtz(kT1, -2), kNop,
                           addiu(kS1, kS1, 1), j(0x80010000), kNop};
  Outcome on = compare(code);
  EXPECT_GT(on.stats.skips, 0u);
  EXPECT_GE(on.s1, 1u);
}

// JOY_STAT: bits 0-10 hold still between events, bits 11-31 are the baud timer, which counts.
TEST(IdleSkip, JoystatPollOnStableBitsIsSkipped) {
  std::vector<u32> code = vblank_wait();
  code[4] = lw(kT2, 0x1044, kT0);
  code[6] = andi(kT2, kT2, 0x200);  // bit 9, the interrupt request (an /ACK that never comes here)
  EXPECT_GT(compare(code).stats.skips, 0u);
}

// The same poll with JOY_BAUD set to a pad's rate (0x88), so that the timer bits read otherwise
// at every examination: the proof knows only the stable bits of the word read, so it serves
// again after each SPU sample event.
TEST(IdleSkip, JoystatPollReusesItsProofWhileTheBaudTimerCounts) {
  std::vector<u32> code = vblank_wait();
  code[4] = lw(kT2, 0x1044, kT0);
  code[6] = andi(kT2, kT2, 0x200);
  code[15] = j(0x8001000C);  // past the two instructions below
  const u32 sh_t4 = itype(0x29, kT0, kT4, 0x104E);  // sh t4, JOY_BAUD(t0)
  code.insert(code.begin() + 1, {ori(kT4, 0, 0x88), sh_t4});
  Outcome on = compare(code, 0x80010000, true);
  EXPECT_GT(on.stats.skips, 4400u);
  EXPECT_LT(on.stats.proofs * 100, on.stats.skips);
}

TEST(IdleSkip, LoopKeepingTheBaudTimerIsNotSkipped) {
  std::vector<u32> code = vblank_wait();
  code[4] = lw(kT2, 0x1044, kT0);
  code[6] = andi(kT5, kT2, 0x200);  // t5 = bit 9, t2 keeps the whole word, timer included
  code[7] = bne(kT5, 0, 5);
  EXPECT_EQ(compare(code).stats.skips, 0u);
}

// The load delay slot stores t2 as it was before the load lands: the 0 the last poll left, the
// same word every iteration, which the skip leaves as the iterations would have.
TEST(IdleSkip, LoopStoringTheSameWordIsSkippedExactly) {
  std::vector<u32> code = vblank_wait();
  code[5] = sw(kT2, 0x100, 0);
  EXPECT_GT(compare(code).stats.skips, 0u);
}

// C's `for (volatile u32 i = 0; i < n; ++i) {}` (Tumble's pad delay): the counter lives in RAM,
// loaded, incremented, stored and loaded again for the test each iteration. s1 counts completed
// delays of 65536 iterations; the load back may use another segment of the same word.
std::vector<u32> volatile_delay(u32 load_back_base_hi) {
  return {lui(kT0, 0x8002), lui(kT2, load_back_base_hi), sw(0, 0x10, kT0),  // i = 0
          lw(kT1, 0x10, kT0), kNop, addiu(kT1, kT1, 1), sw(kT1, 0x10, kT0),  // loop: ++i
          lw(kT1, 0x10, kT2), lui(kT3, 1), sltu(kT4, kT1, kT3), bne(kT4, 0, -8),
          addiu(kT1, 0, 0),  // the delay slot, as GCC fills it
          addiu(kS1, kS1, 1), j(0x80010008), kNop};
}

TEST(IdleSkip, VolatileCounterDelayLoopIsSkippedExactly) {
  Outcome on = compare(volatile_delay(0x8002));
  EXPECT_GT(on.stats.skips, 0u);
  // A skip ends before the delay's exit, so one delay skips fewer than 65536 iterations: more
  // than that means skips in two delays, the first completed (s1, equal both ways: compare()).
  EXPECT_GT(on.stats.iterations, 65536u);
  EXPECT_GE(on.s1, 1u);
}

// With an event every 768 cycles (the SPU at every sample: over 4400 in six frames, nearly all
// of them within a delay) each delay is skipped in hundreds of pieces; after the first, each
// piece repeats from the head, proven again from the counter's value in RAM then, and leaves the
// counter where the iterations would.
TEST(IdleSkip, VolatileCounterDelayRepeatsFromTheCountInMemory) {
  Outcome on = compare(volatile_delay(0x8002), 0x80010000, true);
  EXPECT_GE(on.s1, 1u);
  EXPECT_GT(on.stats.skips, 1000u);
  EXPECT_GT(on.stats.repeats * 10, on.stats.skips * 9);
}

// A memory watch reports every store a loop makes, so no skip may leave one out: a delay proven
// before the watch was attached is not repeated while it is (nor examined: note_store() refuses).
// Two frames of a delay whose iterations take a few dozen cycles store its counter thousands of
// times, one event each, with skipping on as off.
TEST(IdleSkip, StoringLoopIsNotRepeatedUnderAMemoryWatch) {
  std::vector<psx::WatchEvent> events[2];
  for (int skip = 0; skip < 2; ++skip) {
    Console c;
    c.set_idle_skip(skip == 1);
    c.spu().set_max_batch(1);
    const std::vector<u32> code = volatile_delay(0x8002);
    for (u32 i = 0; i < code.size(); ++i) c.write32(0x80010000 + 4 * i, code[i]);
    c.cpu().set_pc(0x80010000);
    c.run_frames(2);
    c.watch("counter", 0x80020010, 4);
    c.run_frames(2);
    events[skip] = c.take_watch_events();
    if (skip == 1) {
      EXPECT_GT(c.idle_skip_stats().repeats, 0u);
    }
  }
  ASSERT_GT(events[0].size(), 1000u);
  EXPECT_EQ(events[1].size(), events[0].size());
}

TEST(IdleSkip, CounterLoadedBackThroughAnotherSegmentIsTheSameWord) {
  Outcome on = compare(volatile_delay(0xA002));  // KSEG1: the same RAM word, uncached
  EXPECT_GT(on.stats.skips, 0u);
  EXPECT_GE(on.s1, 1u);
}

TEST(IdleSkip, ByteLoadFromAStoredWordIsNotSkipped) {
  std::vector<u32> code = volatile_delay(0x8002);
  code[7] = lbu(kT1, 0x10, kT2);  // the counter's low byte: the loop runs for ever, nothing skipped
  EXPECT_EQ(compare(code).stats.skips, 0u);
}

TEST(IdleSkip, LoopStoringThroughAMovingPointerIsNotSkipped) {
  std::vector<u32> code = volatile_delay(0x8002);
  code[6] = sw(kT1, 0x10, kT1);  // stores at i + 10h: another word every iteration
  EXPECT_EQ(compare(code).stats.skips, 0u);
}

TEST(IdleSkip, LoopStoringToIoIsNotSkipped) {
  std::vector<u32> code = vblank_wait();
  code[5] = sw(0, 0x1074, kT0);  // I_MASK, in the load delay slot
  EXPECT_EQ(compare(code).stats.skips, 0u);
}

TEST(IdleSkip, TimerCounterPollIsNotSkipped) {
  // Root counter 0 counts between events: waiting for it to pass 0x8000 cannot jump to an event.
  std::vector<u32> code = {lui(kT0, 0x1F80), lw(kT2, 0x1100, kT0), kNop, andi(kT2, kT2, 0x8000),
                           beq(kT2, 0, -4), kNop, addiu(kS1, kS1, 1), j(0x80010000), kNop};
  EXPECT_EQ(compare(code).stats.skips, 0u);
}

TEST(IdleSkip, GpureadPollIsNotSkipped) {
  std::vector<u32> code = vblank_wait();
  code[4] = lw(kT2, 0x1810, kT0);  // GPUREAD: a read may advance a VRAM download
  EXPECT_EQ(compare(code).stats.skips, 0u);
}

// A jump to address 1, the odd value that marks "no loop head": its fetch raises the address
// error (psx-spx "COP0 - Exception Handling": AdEL, code 4, on an unaligned instruction fetch,
// with EPC and BadVaddr the fetched address), and run() must not take the pc for a loop head
// (it handed the same pc to IdleSkip forever). The vector at 80000080h holds zeros (NOPs) up to
// the program, which jumps there again.
TEST(IdleSkip, JumpToTheNoLoopHeadMarkRaisesTheAddressError) {
  const u32 jr_t0 = kT0 << 21 | 0x08;
  const std::vector<u32> code = {ori(kT0, 0, 1), jr_t0, kNop};
  compare(code);
  for (bool recompiler : {false, true}) {
    Console c;
    c.set_cpu_mode(recompiler ? Console::CpuMode::Recompiler : Console::CpuMode::Interpreter);
    for (u32 i = 0; i < code.size(); ++i) c.write32(0x80010000 + 4 * i, code[i]);
    c.cpu().set_pc(0x80010000);
    c.run_frames(1);
    EXPECT_EQ((c.cpu().cop0().cause >> 2) & 0x1F, 4u);
    EXPECT_EQ(c.cpu().cop0().epc, 1u);
    EXPECT_EQ(c.cpu().cop0().badvaddr, 1u);
  }
}

// Whole programs: the same calls with skipping off and on end in the same save state. Returns the
// skips made.
u64 expect_same(const std::function<void(Console&)>& boot, const std::function<void(Console&)>& play,
                bool expect_skips = true) {
  Console off, on;
  off.set_idle_skip(false);
  boot(off);
  boot(on);
  play(off);
  play(on);
  EXPECT_EQ(off.cycles(), on.cycles());
  EXPECT_EQ(off.instructions(), on.instructions());
  EXPECT_TRUE(off.save_state(false) == on.save_state(false)) << "state differs with idle skipping";
  if (expect_skips) {
    EXPECT_GT(on.idle_skip_stats().skips, 0u);
  }
  return on.idle_skip_stats().skips;
}

TEST(IdleSkipPrograms, TumbleTitle) {
  expect_same([](Console& c) { c.boot_exe(TUMBLE_EXE); }, [](Console& c) { c.run_frames(240); });
}

TEST(IdleSkipPrograms, TumbleLevelWithMoves) {
  expect_same([](Console& c) { c.boot_exe(TUMBLE_EXE); }, tumble_test::play_level_one_moves);
}

TEST(IdleSkipPrograms, CdbootRomBootsTumbleDisc) {
  expect_same(tumble_test::boot_disc_with_cdboot_rom, [](Console& c) { c.run_frames(300); });
}

TEST(IdleSkipPrograms, VsyncCubeWithTimer1OnHblanks) {
  // Waits for the GPU's DMA and for VBlank with timer 1 counting HBlanks, which it takes in closed
  // form (VideoClock::hblanks_by): no event per HBlank edge ends its skips. With one, a frame's
  // wait was cut at each of its 526 edges; without, about 2 skips a frame.
  const u64 skips = expect_same([](Console& c) { c.boot_exe(PSXRL_BUILD_DIR "/bench/vsync_cube.exe"); },
                                [](Console& c) { c.run_frames(240); });
  EXPECT_LT(skips, 240u * 10);
}

TEST(IdleSkipPrograms, TestRoms) {
  for (const char* name : {"gpu_polygons", "dma_modes", "cdrom_controller", "timers_video", "spu_voices", "sio_pad",
                           "cpu_load_timing", "cpu_icache_code"}) {
    SCOPED_TRACE(name);
    const std::string exe = std::string(PSXRL_BUILD_DIR "/tests/roms/") + name + ".exe";
    expect_same([&](Console& c) { c.boot_exe(exe); }, [](Console& c) { c.run_frames(120); }, false);
  }
}

}  // namespace

// A proof is reused for a loop met again j iterations along its line (RegisterLine): registers
// with a step lie at from + j*step, and the others must be as they were unless the loop never
// names them (`any`). The arithmetic below is the expected answer.
TEST(RegisterLine, IterationsAlongTheLineAndFixedRegisters) {
  std::array<u32, 32> before{}, after{};
  for (u32 r = 1; r < 32; ++r) before[r] = after[r] = 0x1000 * r;
  after[kT0] += 3;           // a counter stepping by 3
  after[kS0] -= 8;           // a pointer walking down by 8 (tz 3: j is fixed modulo 2^29)
  const psx::RegisterLine line(before, after);
  EXPECT_TRUE(line.same_steps(before, after));
  std::array<u32, 32> to = before;
  to[kT0] += 3 * 1000, to[kS0] -= 8 * 1000;
  u32 j = 0;
  ASSERT_TRUE(line.iterations(before, to, j));
  EXPECT_EQ(j, 1000u);
  to[kT0] += 1;  // off the line
  EXPECT_FALSE(line.iterations(before, to, j));
  to[kT0] -= 1;
  for (u32 r : {1u, 2u, 29u, 31u}) {  // a register the loop leaves as it is, changed since
    std::array<u32, 32> moved = to;
    moved[r] ^= 0x40;
    EXPECT_FALSE(line.iterations(before, moved, j)) << "r" << r;
    EXPECT_TRUE(line.iterations(before, moved, j, 1u << r)) << "r" << r << " not named by the loop";
    EXPECT_EQ(j, 1000u);
  }
  // advance() walks the line: 1000 steps from `before` reach `to`, 2^32 - 1 steps (one back)
  // from `after` reach `before`, and the registers without a step stay as they were.
  std::array<u32, 32> walked = before;
  line.advance(walked, 1000);
  EXPECT_EQ(walked, to);
  walked = after;
  line.advance(walked, ~0u);
  EXPECT_EQ(walked, before);
}
