// Voices nothing reads stepped a batch at a time (Spu::step_unheard_voices, Voice::step_unheard:
// silent ones, and sounding ones while nothing mixes, their envelopes and sweeps ticking between
// block crossings) and reverb ticks whose value is overwritten unread (Reverb::skip_tick) must
// leave the SPU exactly as the per-sample reference (max batch 1) does: the same save-state bytes
// (sound RAM, voices with their ADPCM history, LSAX, ENDX, reverb histories), the same register
// reads, IRQ9 at the same cycles, and the same output samples where the SPU is observed. The
// workloads have voices that are Off at level 0 while their pitch counters cross blocks with
// LoopStart, LoopEnd and Repeat flags (psx-spx "SPU ADPCM Samples"), pitches from 0 to above 4000h
// (clipped, psx-spx "Pitch Counter"), blocks in the capture buffers (0..FFFh, written every
// sample) and in a reverb work area that ATTR bit 7 lets the reverb write, ENVX written on Off
// voices (their ADPCM history is heard then), PMON and NON on silent voices, key events at any
// cycle, volume sweeps, and IRQA on the blocks silent voices cross, with IRQ9 enabled and with its
// flag left up. Quiet stretches (every voice silent, no CD input: Spu::quiet_samples) follow sound
// in the capture buffers.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "spu_test_util.h"

using namespace psx;
using psx::test::Lcg;
using psx::test::SpuRig;
using psx::test::write_test_volumes_and_reverb;

namespace {

constexpr u32 kAttr = 0x1F801DAA, kIrqA = 0x1F801DA4, kEndx = 0x1F801D9C;
constexpr u16 kAttrOn = 0xC000 | 0x3C00 | 0x0001;  // enable, unmute, noise clock, CD input
constexpr u16 kAttrIrq = 0x0040, kAttrReverb = 0x0080;
// Sound RAM layout (bytes): loops at 1000h, 2000h and 3000h, random blocks from 4000h to 8000h,
// and random blocks filling the reverb work area at ESA = FE00h (7F000h..7FFFFh), which the
// short reverb delays of kTestReverbRegs read and write all over.
constexpr u32 kLoop = 0x1000, kOneBlockLoop = 0x2000, kEndMute = 0x3000, kRandom = 0x4000, kRandomEnd = 0x8000;
constexpr u16 kReverbBase = 0xFE00;
constexpr u32 kInReverbArea = 0x7F000;

// One ADPCM block (psx-spx "SPU ADPCM Samples"): shift 0..12 and filter 0..4 in byte 0, the
// flags in byte 1, 28 random nibbles.
void put_block(u8* ram, u32 addr, u8 flags, Lcg& rng) {
  ram[addr] = static_cast<u8>(rng.next(13) | rng.next(5) << 4);
  ram[addr + 1] = flags;
  for (u32 i = 2; i < 16; ++i) ram[addr + i] = static_cast<u8>(rng.next(256));
}

struct Rig : psx::test::SpuTrace {
  Rig(u32 max_batch, bool observed) {
    spu.set_max_batch(max_batch);
    spu.set_observed(observed);
  }
  // Like the CPU: time moves in instruction-sized steps, now and then a long stall (a DMA
  // transfer), so that an event may run many samples late.
  void run_for(Cycles n, Lcg& steps) {
    SpuTrace::run_for(n, [&] { return steps.next(500) == 0 ? 1 + steps.next(150000) : 1 + steps.next(40); });
  }
};

struct Workload {
  u16 irq_address;   // IRQA, 8-byte units
  bool reverb;       // ATTR bit 7 at first (the reverb writes its work area); EON on voices 0, 7
  u32 seed;
};

void fill_ram(Rig& r, u32 seed) {
  Lcg rng{seed};
  u8* ram = r.spu.ram();
  // Four blocks: LoopStart, two plain, LoopEnd+Repeat (back to the first).
  const u8 loop_flags[4] = {4, 0, 0, 3};
  for (u32 b = 0; b < 4; ++b) put_block(ram, kLoop + 16 * b, loop_flags[b], rng);
  put_block(ram, kOneBlockLoop, 7, rng);  // LoopStart+LoopEnd+Repeat on itself
  // Two plain blocks and LoopEnd without Repeat: End+Mute, then on at LSAX.
  for (u32 b = 0; b < 3; ++b) put_block(ram, kEndMute + 16 * b, b == 2 ? 1 : 0, rng);
  // Mostly plain blocks, some LoopStart, some LoopEnd with or without Repeat.
  auto random_flags = [&] {
    const u32 k = rng.next(16);
    return static_cast<u8>(k < 11 ? 0 : k < 13 ? 4 : k < 15 ? 3 : 1);
  };
  for (u32 a = kRandom; a < kRandomEnd; a += 16) put_block(ram, a, random_flags(), rng);
  for (u32 a = kInReverbArea; a < Spu::kRamSize; a += 16) put_block(ram, a, random_flags(), rng);
  // The rest of the capture area and the reverb area keep their contents: zeros, then whatever
  // the SPU writes there.
}

u32 some_address(Lcg& ops) {
  const u32 where[] = {0x0000, 0x0400, 0x0F80, kLoop, kOneBlockLoop, kEndMute, kInReverbArea, kInReverbArea + 0x400};
  const u32 k = ops.next(11);
  return k < 8 ? where[k] : kRandom + 16 * ops.next((kRandomEnd - kRandom) / 16);
}

u16 some_pitch(Lcg& ops) {
  const u16 pitches[] = {0, 1, 0x10, 0x0123, 0x0800, 0x1000, 0x3FFF, 0x4000, 0xFFFF};
  const u32 k = ops.next(11);
  return k < 9 ? pitches[k] : static_cast<u16>(ops.next(0x10000));
}

void set_up(Rig& r, const Workload& w) {
  fill_ram(r, w.seed);
  write_test_volumes_and_reverb(r);
  r.w16(0x1F801DA2, kReverbBase);
  Lcg ops{w.seed * 3 + 1};
  // Every voice starts somewhere; none is keyed yet, so all are Off at level 0 and walk from
  // address 0 (the capture buffers) at their pitch until keyed.
  for (u32 v = 0; v < Spu::kNumVoices; ++v) {
    r.voice_w(v, 0x0, 0x3FFF);
    r.voice_w(v, 0x2, 0x2000);
    r.voice_w(v, 0x4, some_pitch(ops));
    r.voice_w(v, 0x6, static_cast<u16>(some_address(ops) / 8));
    r.voice_w(v, 0x8, 0x00FF);                           // fast attack, sustain level max
    r.voice_w(v, 0xA, v % 3 == 0 ? 0x1FC0 : 0x0000);     // slow or instant release
  }
  r.w16(0x1F801D90, 0x0C06);  // PMON: voices 1, 2, 10, 11
  r.w16(0x1F801D94, 0x1030);  // NON: voices 4, 5, 12
  r.w16(0x1F801D98, 0x0081);  // EON: voices 0 and 7
  r.w16(kIrqA, w.irq_address);
  r.w16(0x1F801DAC, 0x0004);  // capture-buffer writes check IRQA too
  r.w16(kAttr, kAttrOn | (w.reverb ? kAttrReverb : 0));
}

// One step: time passes, then one register access or RAM change.
void operate(Rig& r, const Workload& w, Lcg& ops, Lcg& steps) {
  r.run_for(1 + ops.next(ops.next(4) == 0 ? 400000 : 20000), steps);
  const u32 v = ops.next(Spu::kNumVoices);
  const u16 base = r.attr & ~kAttrIrq;
  switch (ops.next(14)) {
    case 0: case 1: r.w16(0x1F801D88 + 2 * (v / 16), static_cast<u16>(1u << (v % 16))); break;  // KON
    case 2: case 3: r.w16(0x1F801D8C + 2 * (v / 16), static_cast<u16>(1u << (v % 16))); break;  // KOFF
    case 4: r.r16(kEndx), r.r16(kEndx + 2); break;
    // ENVX of a voice: heard from the next sample on (an Off voice stays at it), or back to 0.
    case 5: r.voice_w(v, 0xC, ops.next(2) ? 0 : static_cast<u16>(ops.next(0x8000))); break;
    case 6: r.voice_w(v, 0x4, some_pitch(ops)); break;
    case 7: r.voice_w(v, ops.next(2) ? 0x6 : 0xE, static_cast<u16>(some_address(ops) / 8)); break;  // SSA/LSAX
    case 8: r.w16(ops.next(2) ? 0x1F801D90 : 0x1F801D94, static_cast<u16>(ops.next(0x10000))); break;  // PMON/NON
    case 9: {  // IRQ9 on, acknowledged and on again, or off: the flag stays up until acknowledged;
      // IRQA moved; reverb writes switched
      const u32 k = ops.next(5);
      if (k == 0) r.w16(kAttr, base | kAttrIrq);
      if (k == 1) r.w16(kAttr, base), r.w16(kAttr, base | kAttrIrq);
      if (k == 2) r.w16(kAttr, base);
      if (k == 3) r.w16(kIrqA, ops.next(2) ? w.irq_address : static_cast<u16>(some_address(ops) / 8 + 2 * ops.next(4)));
      if (k == 4) r.w16(kAttr, r.attr ^ kAttrReverb);
      break;
    }
    case 10: {  // a sweep (bit 15; bits 12-14 mode, direction, phase; bits 0-6 rate) or a fixed volume
      const u16 sweep = static_cast<u16>(0x8000 | ops.next(8) << 12 | ops.next(0x7F));
      r.voice_w(v, 2 * ops.next(2), ops.next(3) == 0 ? sweep : 0x3FFF);
      break;
    }
    case 11: {  // the host changes a block some voice may read
      Lcg rng{ops.next(1000)};
      put_block(r.spu.ram(), some_address(ops), static_cast<u8>(ops.next(8)), rng);
      break;
    }
    case 12: r.take(); break;
    default: r.r16(0x1F801C0C + 0x10 * v); break;  // ENVX
  }
}

void expect_same(Rig& a, Rig& b, bool outputs, const std::string& what) {
  ASSERT_EQ(a.state(), b.state()) << what;
  ASSERT_EQ(a.reads, b.reads) << what;
  ASSERT_EQ(a.irq_times, b.irq_times) << what;
  if (!outputs) return;
  a.take();
  b.take();
  ASSERT_EQ(a.out.size(), b.out.size()) << what;
  for (size_t i = 0; i < a.out.size(); ++i)
    ASSERT_TRUE(a.out[i].left == b.out[i].left && a.out[i].right == b.out[i].right) << what << " sample " << i;
}

// The workload on the reference (max batch 1, observed), on batching SPUs observed and not, and
// on a per-sample one not observed; all compared every 50 steps. Returns the IRQ9 count.
size_t compare(const Workload& w) {
  std::vector<std::unique_ptr<Rig>> rigs;
  rigs.push_back(std::make_unique<Rig>(1, true));
  rigs.push_back(std::make_unique<Rig>(Spu::kDefaultMaxBatch, true));
  rigs.push_back(std::make_unique<Rig>(Spu::kDefaultMaxBatch, false));
  rigs.push_back(std::make_unique<Rig>(1, false));
  for (auto& r : rigs) set_up(*r, w);
  std::vector<Lcg> ops(rigs.size(), Lcg{w.seed}), steps(rigs.size(), Lcg{w.seed * 7 + 3});
  for (u32 round = 0; round < 12; ++round) {
    for (size_t i = 0; i < rigs.size(); ++i)
      for (u32 k = 0; k < 50; ++k) operate(*rigs[i], w, ops[i], steps[i]);
    for (size_t i = 1; i < rigs.size(); ++i) {
      expect_same(*rigs[0], *rigs[i], i == 1, "rig " + std::to_string(i) + " round " + std::to_string(round));
      if (::testing::Test::HasFatalFailure()) return 0;
    }
  }
  return rigs[0]->irq_times.size();
}

}  // namespace

TEST(SpuSilent, BatchesMatchPerSampleWithIrqOnLoopBlocks) {
  // IRQA on the second block of the four-block loop, which silent voices cross again and again.
  EXPECT_GE(compare({static_cast<u16>(kLoop / 8 + 2), false, 1}), 5u);
}

TEST(SpuSilent, BatchesMatchPerSampleWithIrqInCaptureBuffers) {
  EXPECT_GE(compare({static_cast<u16>(0x0400 / 8 + 16), false, 2}), 5u);
}

TEST(SpuSilent, BatchesMatchPerSampleWithReverbWritingBlocksVoicesRead) {
  // ATTR bit 7 set: the reverb writes the work area that holds some voices' blocks.
  compare({static_cast<u16>(kRandom / 8 + 40), true, 3});
}

TEST(SpuSilent, BatchesMatchPerSampleWithIrqInReverbArea) {
  compare({static_cast<u16>(kInReverbArea / 8 + 6), true, 4});
}

TEST(SpuSilent, BatchesMatchPerSampleOtherSeeds) {
  // IRQA in the work area while the reverb only reads it; on random blocks with and without
  // reverb writes.
  for (const Workload& w : {Workload{static_cast<u16>(kInReverbArea / 8 + 100), false, 5},
                            Workload{static_cast<u16>(kRandom / 8 + 12), true, 6},
                            Workload{static_cast<u16>(kRandom / 8 + 14), false, 7}}) {
    compare(w);
    if (HasFatalFailure()) return;
  }
}

namespace {

// When I_STAT bit 9 is first seen: stepping sample by sample, except for one stall of `stall`
// cycles after `before` samples (as a long DMA transfer stalls the CPU) followed by a SPUSTAT
// read, which makes the stalled samples in one catch-up before the late event runs (inside its
// callback an event makes only the samples due by its own turn). Every voice sits Off at level
// 0 on block 0 (never keyed) at pitch 0, except voice 5 at 4000h (4 ADPCM samples per output
// sample: a block every 7 samples, psx-spx "Pitch Counter"); IRQ9 is on, the capture buffers do
// not check IRQA (RAM_CTRL 0) and the reverb, writes off, runs on the work area at ESA = FE00h
// (halfwords 3F800h on) with all offsets 0: each tick it reads its buffer address, which moves
// one halfword every second tick (psx-spx "SPU Reverb Formula").
Cycles first_irq(u32 max_batch, u16 irq_address, u32 before, Cycles stall) {
  SpuRig r;
  r.spu.set_max_batch(max_batch);
  r.spu.set_observed(false);
  r.w16(0x1F801DA2, 0xFE00);
  r.voice_w(5, 0x4, 0x4000);
  r.w16(kIrqA, irq_address);
  r.w16(kAttr, 0x8000 | kAttrIrq);
  const u32 irq9 = 1u << static_cast<u32>(Irq::Spu);
  for (u32 i = 0; i < 3000 && !(r.irq.stat() & irq9); ++i) {
    if (i == before) {
      r.sched.advance(stall);
      r.r16(0x1F801DAE);
      r.sched.run_due_events();
      if (r.irq.stat() & irq9) break;
    }
    r.run_samples(1);
  }
  return (r.irq.stat() & irq9) ? r.sched.now() : 0;
}

}  // namespace

TEST(SpuSilent, SilentVoiceAndUnheardReverbRaiseIrq9InALateCatchUp) {
  // Voice 5 is in block k during samples 7k+1..7k+7 (sample k due at k * 768 cycles) and reads
  // its header at IRQA = 220h (byte 1100h, block 272, past the capture buffers that the SPU
  // writes) in sample 1905. The reverb's buffer address is halfword 3F800h + (t-1)/2 in tick t,
  // in 8-byte unit FE0Ah from tick 81 on.
  const u16 voice_block = 0x220, reverb_unit = 0xFE0A;
  const Cycles stall = 400 * Spu::kCyclesPerSample;
  for (u32 batch : {1u, Spu::kDefaultMaxBatch}) {
    EXPECT_EQ(first_irq(batch, voice_block, 9999, 0), 1905u * Spu::kCyclesPerSample) << batch;
    EXPECT_EQ(first_irq(batch, reverb_unit, 9999, 0), 81u * Spu::kCyclesPerSample) << batch;
    // Samples 1801..2200 and 1..400 made in one catch-up: the hits raise IRQ9 at its end.
    EXPECT_EQ(first_irq(batch, voice_block, 1800, stall), 2200u * Spu::kCyclesPerSample) << batch;
    EXPECT_EQ(first_irq(batch, reverb_unit, 0, stall), 400u * Spu::kCyclesPerSample) << batch;
  }
}

namespace {

// Quiet stretches (Spu::quiet_samples): every voice silent, no CD input, nothing heard of the
// reverb. Voices 1 and 3 play one End+Mute block (28 samples into the capture buffers, then
// silent) and the CD input a few hundred frames, again every round, so that quiet samples write
// zeros over sound (600 at once after a stall: all 200h positions); the other voices sit Off on
// a one-block loop. ATTR has `attr_bits` too. The reverb works at ESA (its area from FE00h
// filled with noise), writing it where ATTR bit 7 is set; EVOL is 0 for three rounds and a
// third, so observed SPUs go quiet too and their output is compared, then `evol` (heard: not
// quiet where observed, and the values owed meanwhile are heard); the main volume sweeps down
// from 3FFFh.
void quiet_workload(Rig& r, Lcg& steps, u16 esa, u16 attr_bits, u16 evol = 0x3000) {
  Lcg data{17};
  put_block(r.spu.ram(), kOneBlockLoop, 7, data);
  for (u32 a = kInReverbArea; a < Spu::kRamSize; a += 16) put_block(r.spu.ram(), a, 0, data);
  for (u32 v : {1u, 3u}) put_block(r.spu.ram(), kEndMute + 16 * v, 1, data);
  for (u32 v = 0; v < Spu::kNumVoices; ++v) r.voice_w(v, 0x6, static_cast<u16>(kOneBlockLoop / 8));
  write_test_volumes_and_reverb(r);
  r.w16(0x1F801D84, 0);  // EVOLL/EVOLR
  r.w16(0x1F801D86, 0);
  r.w16(0x1F801DA2, esa);
  r.w16(kAttr, kAttrOn | attr_bits);
  r.run_for(4 * Spu::kCyclesPerSample, steps);  // MVOLL 3FFFh (fixed) latched
  r.w16(0x1F801D80, 0xA000 | 10 << 2);           // then a linear sweep down from there
  for (u32 round = 0; round < 6; ++round) {
    for (u32 i = 0; i < 300; ++i) r.cd.push({static_cast<s16>(i * 37 + 1), static_cast<s16>(-static_cast<s32>(i) * 41 - 1)});
    for (u32 v : {1u, 3u}) {
      r.voice_w(v, 0x0, 0x3FFF);
      r.voice_w(v, 0x2, 0x3FFF);
      r.voice_w(v, 0x4, 0x1000);
      r.voice_w(v, 0x6, static_cast<u16>((kEndMute + 16 * v) / 8));
      r.voice_w(v, 0x8, 0x00FF);
      r.voice_w(v, 0xA, 0x1FC0);
    }
    r.w16(0x1F801D88, (1u << 1) | (1u << 3));  // KON
    r.run_for(100 * Spu::kCyclesPerSample, steps);
    // Heard from here, with the CD input still playing (into the reverb, with ATTR bit 2).
    if (round == 3) r.w16(0x1F801D84, evol), r.w16(0x1F801D86, evol);
    // Muted since sample 28; pitch 0 keeps them on their block (their End flag would set ENDX
    // every 28 samples, which a silent voice steps sample by sample).
    for (u32 v : {1u, 3u}) r.voice_w(v, 0x4, 0);
    // A stall (a long DMA) ending in a SPUSTAT read makes 800 samples in one catch-up: the
    // rest of the CD input, then quiet ones over it, across the capture buffers' end. The last
    // round ends there, for the comparison to see the buffers as the stall left them.
    if (round % 2 == 1) {
      r.sched.advance(800 * Spu::kCyclesPerSample);
      r.r16(0x1F801DAE);
      r.sched.run_due_events();
    }
    if (round == 5) break;
    // 3072 samples a round: the main volume's sweep is still above 0 when EVOL is set.
    r.run_for(3072 * Spu::kCyclesPerSample, steps);
    r.take();
  }
}

}  // namespace

namespace {

// The quiet workload on the reference (max batch 1, observed) and on batching SPUs observed and
// not.
void compare_quiet(u16 esa, u16 attr_bits) {
  std::vector<std::unique_ptr<Rig>> rigs;
  rigs.push_back(std::make_unique<Rig>(1, true));
  rigs.push_back(std::make_unique<Rig>(Spu::kDefaultMaxBatch, true));
  rigs.push_back(std::make_unique<Rig>(Spu::kDefaultMaxBatch, false));
  for (auto& r : rigs) {
    Lcg steps{29};
    quiet_workload(*r, steps, esa, attr_bits);
  }
  for (size_t i = 1; i < rigs.size(); ++i) {
    expect_same(*rigs[0], *rigs[i], i == 1, "rig " + std::to_string(i));
    if (::testing::Test::HasFatalFailure()) return;
  }
  // The workload made sound: the capture buffers' quiet zeros overwrite something.
  bool sound = false;
  for (const StereoSample& s : rigs[0]->out) sound |= s.left != 0 && s.right != 0;
  EXPECT_TRUE(sound);
  // The reverb was heard: without it (EVOL 0 throughout) the output differs.
  Rig dry(1, true);
  Lcg steps{29};
  quiet_workload(dry, steps, esa, attr_bits, 0);
  dry.take();
  ASSERT_EQ(dry.out.size(), rigs[0]->out.size());
  bool wet = false;
  for (size_t i = 0; i < dry.out.size(); ++i)
    wet |= dry.out[i].left != rigs[0]->out[i].left || dry.out[i].right != rigs[0]->out[i].right;
  EXPECT_TRUE(wet);
}

}  // namespace

TEST(SpuSilent, QuietStretchesAfterSoundMatchPerSample) {
  compare_quiet(kReverbBase, kAttrReverb);
}

TEST(SpuSilent, QuietStretchesWithUnseenReverbMatchPerSample) {
  // ATTR bit 7 clear and EVOL 0: nothing sees the reverb's ticks, whose values are skipped or
  // owed (Reverb::quiet_ticks), until EVOL makes them heard. At ESA = FE00h its reads never reach
  // the capture buffers; at ESA = 0 (the whole of sound RAM) they start there, at its buffer
  // address 0, and leave them 800h halfwords (4096 ticks) later.
  compare_quiet(kReverbBase, 0);
  if (HasFatalFailure()) return;
  compare_quiet(0, 0);
  if (HasFatalFailure()) return;
  // ATTR bit 2: the CD input feeds the unseen reverb (and its values stay owed).
  compare_quiet(kReverbBase, 0x0004);
}

TEST(SpuSilent, UnseenReverbKeepsTheInputHistoryItIsFed) {
  // Unseen, the reverb's input history is still state (saved, and read once ATTR bit 7 lets it
  // write): with ATTR bit 2 the CD input feeds it, so its ticks are not made ahead of the
  // samples. Compared while the CD input plays.
  Rig reference(1, false), batched(Spu::kDefaultMaxBatch, false);
  for (Rig* r : {&reference, &batched}) {
    Lcg steps{31};
    write_test_volumes_and_reverb(*r);
    r->w16(0x1F801D84, 0);  // EVOLL/EVOLR
    r->w16(0x1F801D86, 0);
    r->w16(0x1F801DA2, kReverbBase);
    r->w16(kAttr, kAttrOn | 0x0004);
    for (u32 i = 0; i < 600; ++i) r->cd.push({static_cast<s16>(i * 53 + 7), static_cast<s16>(-static_cast<s32>(i) * 29 - 3)});
    r->run_for(300 * Spu::kCyclesPerSample, steps);
  }
  expect_same(reference, batched, false, "CD input into the reverb");
}

namespace {

// Voices 1 and 3 sounding while nothing mixes: only their capture buffers read them, so a
// batching SPU steps them ahead through a catch-up and writes the buffers from the outputs it
// kept (Spu::step_unheard_voices, Voice::step_captured), in sample-by-sample catch-ups and in
// quiet stretches (every other voice silent or unread). They play the four-block loop, random
// blocks, blocks in the capture buffers and in the reverb work area (where the SPU writes: a
// later block read there sends them back to sample by sample), through ADSR phases, key off and
// on, ENVX writes and pitch changes, with PMON, EON and NON switched on and off for voices 1 to 4
// (which make them needed otherwise, or their output noise); voices 2 and 5 sound unread, unless
// voice 2 modulates voice 3. Stalls make
// catch-ups of 800 samples, across the buffers' end.
struct CapturedWorkload {
  Lcg ops, steps;
  static constexpr u32 kSounding[4] = {1, 2, 3, 5};

  CapturedWorkload(Rig& r, u32 seed) : ops{seed}, steps{seed * 5 + 1} {
    fill_ram(r, seed);
    write_test_volumes_and_reverb(r);
    r.w16(0x1F801D84, 0);  // EVOLL/EVOLR: the reverb unheard
    r.w16(0x1F801D86, 0);
    r.w16(0x1F801DA2, kReverbBase);
    for (u32 v = 0; v < Spu::kNumVoices; ++v) {
      r.voice_w(v, 0x4, some_pitch(ops));
      r.voice_w(v, 0x6, static_cast<u16>(kOneBlockLoop / 8));
      r.voice_w(v, 0x8, 0x00FF);
    }
    for (u32 v : kSounding) {
      r.voice_w(v, 0x0, 0x3FFF);
      r.voice_w(v, 0x2, 0x2000);
      r.voice_w(v, 0x6, static_cast<u16>((v == 5 ? kRandom : kLoop) / 8));
      r.voice_w(v, 0x8, 0x00FF);  // fast attack, sustain level max
      r.voice_w(v, 0xA, 0x1FC0);  // slow release
    }
    r.w16(kAttr, kAttrOn);
    // Every voice keyed on, so that the silent ones walk their one-block loop rather than the
    // capture buffers; all but the sounding ones keyed off again (instant release: ADSR2 0).
    r.w16(0x1F801D88, 0xFFFF);  // KON
    r.w16(0x1F801D8A, 0x00FF);
    r.run_for(10 * Spu::kCyclesPerSample, steps);
    r.w16(0x1F801D8C, static_cast<u16>(~((1u << 1) | (1u << 2) | (1u << 3) | (1u << 5))));  // KOFF
    r.w16(0x1F801D8E, 0x00FF);
  }

  // Time passes, then one register access.
  void operate(Rig& r) {
    r.run_for(1 + ops.next(20000), steps);
    const u32 v = kSounding[ops.next(4)];
    switch (ops.next(12)) {
      case 0: case 1: r.w16(0x1F801D88, static_cast<u16>(1u << v)); break;  // KON
      case 2: r.w16(0x1F801D8C, static_cast<u16>(1u << v)); break;          // KOFF
      case 3: r.voice_w(v, 0xC, static_cast<u16>(ops.next(0x8000))); break;  // ENVX
      case 4: r.voice_w(v, 0x4, some_pitch(ops)); break;
      case 5: r.voice_w(v, ops.next(2) ? 0x6 : 0xE, static_cast<u16>(some_address(ops) / 8)); break;  // SSA/LSAX
      case 6:  // PMON, NON or EON on some of voices 1 to 4, or on none
        r.w16(0x1F801D90 + 4 * ops.next(3), static_cast<u16>(ops.next(2) == 0 ? ops.next(16) << 1 : 0));
        break;
      case 7: r.w16(kAttr, r.attr ^ kAttrReverb); break;
      case 8:  // a long DMA stall ending in a SPUSTAT read
        r.sched.advance(800 * Spu::kCyclesPerSample);
        r.r16(0x1F801DAE);
        r.sched.run_due_events();
        break;
      case 9: r.voice_w(v, 0x8 + 2 * ops.next(2), static_cast<u16>(ops.next(0x10000))); break;  // ADSR1/2
      case 10: r.take(); break;
      default: r.r16(kEndx); break;
    }
  }
};

}  // namespace

TEST(SpuSilent, VoicesReadOnlyByTheirCaptureBuffersMatchPerSample) {
  for (u32 seed : {41u, 42u, 43u}) {
    // Batching, unobserved and observed (where the mix reads every voice).
    Rig reference(1, true), batched(Spu::kDefaultMaxBatch, false), heard(Spu::kDefaultMaxBatch, true);
    CapturedWorkload a(reference, seed), b(batched, seed), c(heard, seed);
    for (u32 i = 0; i < 300; ++i) {
      a.operate(reference);
      b.operate(batched);
      c.operate(heard);
      expect_same(reference, batched, false, "seed " + std::to_string(seed) + " step " + std::to_string(i));
      expect_same(reference, heard, true, "heard, seed " + std::to_string(seed) + " step " + std::to_string(i));
      if (HasFatalFailure()) return;
    }
  }
}
