// Lazy SPU (spu/spu.h): samples made in batches when something observes the SPU must be exactly
// the samples an event at every sample makes. SPUs batching at most 1 (the reference), 7 and the
// default samples run the same register, DMA and CD-audio workload under a CPU-like driver (time
// in uneven steps, events dispatched once a step reaches the deadline); read values, IRQ9 times,
// output samples and state bytes must match. Also: a CD push tied with a sample keeps the event
// order, a guest loop polling SPUSTAT under idle skipping sees every bit 11 flip on time, Tumble's
// title and a level with and without idle skipping, and a save state taken in a batch's middle.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "spu/adpcm.h"
#include "spu_test_util.h"
#include "tumble_console_util.h"

using namespace psx;
using psx::test::Lcg;
using psx::test::write_test_volumes_and_reverb;

namespace {

constexpr u32 kSine = 0x1000, kOneShot = 0x3000;
constexpr u16 kReverbBase = 0xFE00;  // ESA (8-byte units): a 4 KiB work area at 7F000h
constexpr u32 kStat = 0x1F801DAE, kAttr = 0x1F801DAA, kIrqA = 0x1F801DA4, kRamCtrl = 0x1F801DAC;
constexpr u16 kAttrOn = 0xC000 | 0x3C00 | 0x0080 | 0x0005;  // enable, unmute, noise, reverb, CD
constexpr u16 kAttrIrq = 0x0040;

std::vector<u8> sine_blocks(double amplitude, size_t period, bool loop) {
  std::vector<s16> pcm(period * 28);
  for (size_t i = 0; i < pcm.size(); ++i) pcm[i] = static_cast<s16>(std::lround(amplitude * std::sin(2 * M_PI * i / period)));
  spu::AdpcmEncodeOptions o;
  o.loop = loop;
  return spu::encode_adpcm(pcm.data(), pcm.size(), o);
}

// A standalone SPU with two CD feeding events, one registered before the SPU's event and one
// after (ties with a sample go to the lower handle), driven like the CPU drives the console.
struct Rig : psx::test::SpuTrace {
  Scheduler::Handle feed_after = sched.add_event("feed.after", [this](Cycles late) { feed(feed_after, 1, late); });
  Lcg feed_rng[2] = {{11}, {23}};
  s16 cd_value = 0;

  explicit Rig(u32 max_batch) {
    before_spu_event = [this](Cycles late) { feed(before_spu, 0, late); };
    spu.set_max_batch(max_batch);
    sched.schedule(before_spu, 7 * Spu::kCyclesPerSample);
    sched.schedule(feed_after, 9 * Spu::kCyclesPerSample);
  }
  // A CD sector's worth of frames at a time, at times often on the sample grid (a tie with a
  // sample): sometimes more than the SPU takes (the FIFO fills and drops), with gaps where it
  // runs dry.
  void feed(Scheduler::Handle h, int which, Cycles late) {
    Lcg& r = feed_rng[which];
    const u32 n = r.next(4) == 0 ? 3000 : r.next(600);
    for (u32 i = 0; i < n; ++i, cd_value = static_cast<s16>(cd_value + 97)) cd.push({cd_value, static_cast<s16>(-cd_value)});
    const Cycles gap = r.next(2) ? Cycles{768} * (1 + r.next(700)) : 1 + r.next(400000);
    sched.schedule_at(h, sched.now() - late + gap);
  }
  // Like the CPU: time moves in instruction-sized steps.
  void run_for(Cycles n, Lcg& steps) {
    SpuTrace::run_for(n, [&] { return 1 + steps.next(30); });
  }
};

void voice(Rig& r, u32 v, u32 byte_addr, u16 pitch, u16 vol, u16 adsr1, u16 adsr2) {
  const u32 base = 0x1F801C00 + v * 0x10;
  r.w16(base + 0x0, vol);
  r.w16(base + 0x2, vol);
  r.w16(base + 0x4, pitch);
  r.w16(base + 0x6, static_cast<u16>(byte_addr / 8));
  r.w16(base + 0x8, adsr1);
  r.w16(base + 0xA, adsr2);
}

void set_up(Rig& r, u16 irq_address) {
  const std::vector<u8> sine = sine_blocks(12000, 32, true), one_shot = sine_blocks(9000, 20, false);
  std::copy(sine.begin(), sine.end(), r.spu.ram() + kSine);
  std::copy(one_shot.begin(), one_shot.end(), r.spu.ram() + kOneShot);
  // 0: plain; 1 and 3 (noise) reach the capture buffers; 2 and 7 (one-shot: ENDX) the reverb;
  // 4 modulates 5; 8 has a slow attack (its level is read back).
  voice(r, 0, kSine, 0x0800, 0x3FFF, 0x00FF, 0x1FC0);
  voice(r, 1, kSine, 0x1000, 0x3000, 0x00FF, 0x1FC0);
  voice(r, 2, kSine, 0x0C00, 0x2000, 0x00FF, 0x1FC0);
  voice(r, 3, kSine, 0x1000, 0x1800, 0x00FF, 0x1FC0);
  voice(r, 4, kSine, 0x1800, 0x3FFF, 0x00FF, 0x1FC0);
  voice(r, 5, kSine, 0x1000, 0x3000, 0x00FF, 0x1FC0);
  voice(r, 7, kOneShot, 0x1200, 0x3FFF, 0x00FF, 0x1FC0);
  voice(r, 8, kSine, 0x0A00, 0x3FFF, 0x5A3F, 0x5FD0);
  r.w16(0x1F801D90, 0x0020);  // PMON: voice 5
  r.w16(0x1F801D94, 0x0008);  // NON: voice 3
  r.w16(0x1F801D98, 0x0084);  // EON: voices 2 and 7
  write_test_volumes_and_reverb(r);
  r.w16(0x1F801DA2, kReverbBase);
  r.w16(kIrqA, irq_address);
  r.w16(kRamCtrl, 0x0004);  // capture-buffer writes check IRQA too
  r.w16(kAttr, kAttrOn);
  r.w16(0x1F801D88, 0x01BF);  // KON voices 0-5, 7, 8
}

// One step of the workload, chosen by `ops`: register traffic, transfers, key events, IRQ9
// enabling, acknowledging and disabling, output taking and listening switches.
void operate(Rig& r, Lcg& ops, Lcg& steps) {
  r.run_for(1 + ops.next(60000), steps);
  switch (ops.next(12)) {
    case 0: r.r16(kStat); break;
    case 1: r.r16(0x1F801D9C), r.r16(0x1F801D9E); break;  // ENDX
    case 2: r.r16(0x1F801C8C), r.r16(0x1F801C1C); break;  // ADSR levels of voices 8 and 1
    case 3: r.w16(0x1F801D88, static_cast<u16>(1u << ops.next(9))); break;  // KON
    case 4: r.w16(0x1F801D8C, static_cast<u16>(1u << ops.next(9))); break;  // KOFF
    case 5: {  // IRQ9 on, or acknowledged (bit 6 low, then high again), or off
      const u32 k = ops.next(3);
      if (k == 0) r.w16(kAttr, kAttrOn | kAttrIrq);
      if (k == 1) r.w16(kAttr, kAttrOn), r.w16(kAttr, kAttrOn | kAttrIrq);
      if (k == 2) r.w16(kAttr, kAttrOn);
      break;
    }
    case 6: {  // DMA write into the capture, voice or reverb area, then read it back
      const u16 tsa = static_cast<u16>(ops.next(3) == 0 ? ops.next(0x200) : 0x200 + ops.next(0xFE00));
      u32 words[16];
      for (u32& w : words) w = ops.next(0x10000) * 0x10001u;
      const u16 attr = r.attr;
      r.w16(0x1F801DA6, tsa);
      r.w16(kAttr, attr | 0x0020);  // DMA write mode (IRQ9 as it was: transfers check IRQA too)
      r.run_for(1 + ops.next(3000), steps);  // the DMA controller starts later
      r.spu.dma_write(words, 16);
      r.note_irq();
      r.w16(0x1F801DA6, tsa);
      r.w16(kAttr, attr | 0x0030);  // DMA read mode
      r.run_for(1 + ops.next(3000), steps);
      r.spu.dma_read(words, 16);
      r.note_irq();
      for (u32 w : words) r.reads.push_back(w);
      r.w16(kAttr, attr);
      break;
    }
    case 7: {  // manual FIFO writes into the capture area
      const u16 attr = r.attr;
      r.w16(0x1F801DA6, static_cast<u16>(ops.next(0x200)));
      for (u32 i = 0; i < 8; ++i) r.w16(0x1F801DA8, static_cast<u16>(ops.next(0x10000)));
      r.w16(kAttr, attr | 0x0010);
      r.w16(kAttr, attr);
      break;
    }
    case 8: r.take(); break;
    case 9: r.spu.set_observed(ops.next(2) == 0); break;
    case 10: r.w16(0x1F801C04 + 0x10 * ops.next(9), static_cast<u16>(0x400 + ops.next(0x1800))); break;  // pitch
    default: r.r16(0x1F801DB8), r.r16(0x1F801DBA); break;  // current main volume
  }
}

void expect_same(Rig& a, Rig& b, const char* what) {
  ASSERT_EQ(a.state(), b.state()) << what;
  ASSERT_EQ(a.reads, b.reads) << what;
  ASSERT_EQ(a.irq_times, b.irq_times) << what;
  a.take();
  b.take();
  ASSERT_EQ(a.out.size(), b.out.size()) << what;
  for (size_t i = 0; i < a.out.size(); ++i)
    ASSERT_TRUE(a.out[i].left == b.out[i].left && a.out[i].right == b.out[i].right) << what << " " << i;
  ASSERT_EQ(a.cd.size(), b.cd.size()) << what;
}

// The workload on SPUs batching at most 1, 7 and 256 samples, compared every 40 steps.
void compare_batching(u16 irq_address, u32 seed) {
  auto rigs = std::vector<std::unique_ptr<Rig>>();
  for (u32 batch : {1u, 7u, Spu::kDefaultMaxBatch}) rigs.push_back(std::make_unique<Rig>(batch));
  for (auto& r : rigs) set_up(*r, irq_address);
  std::vector<Lcg> ops(rigs.size(), Lcg{seed}), steps(rigs.size(), Lcg{seed * 7 + 1});
  for (u32 round = 0; round < 15; ++round) {
    for (size_t i = 0; i < rigs.size(); ++i)
      for (u32 k = 0; k < 40; ++k) operate(*rigs[i], ops[i], steps[i]);
    for (size_t i = 1; i < rigs.size(); ++i) {
      expect_same(*rigs[0], *rigs[i], ("round " + std::to_string(round)).c_str());
      if (::testing::Test::HasFatalFailure()) return;
    }
  }
  // The workload reached what it is meant to: IRQ9 fired (and was acknowledged) many times.
  EXPECT_GE(rigs[0]->irq_times.size(), 10u);
}

}  // namespace

TEST(SpuLazy, BatchesMatchPerSampleWithIrqAddressInVoiceData) { compare_batching(kSine / 8 + 1, 1); }
TEST(SpuLazy, BatchesMatchPerSampleWithIrqAddressInCaptureBuffers) { compare_batching(0x0408 / 8, 2); }
TEST(SpuLazy, BatchesMatchPerSampleWithIrqAddressInReverbArea) { compare_batching(kReverbBase + 0x40, 3); }

TEST(SpuLazy, EventsBatchWhileIrq9CannotFire) {
  // Booking: one event per batch while IRQ9 is off (kDefaultMaxBatch samples, or up to where
  // SPUSTAT bit 11 flips, every 256 samples from power-on, once idle skipping has asked for
  // that), one per sample while it could fire.
  Rig r(Spu::kDefaultMaxBatch);
  set_up(r, 0x0408 / 8);
  r.spu.sync();
  const auto samples_to_event = [&r] {
    const Cycles next = r.sched.when(r.sched.find("spu.sample"));
    return (next - r.sched.now() + Spu::kCyclesPerSample - 1) / Spu::kCyclesPerSample;
  };
  EXPECT_EQ(samples_to_event(), Spu::kDefaultMaxBatch);
  EXPECT_TRUE(r.spu.end_batches_at_flips());
  EXPECT_FALSE(r.spu.end_batches_at_flips());  // asked once is enough
  EXPECT_EQ(samples_to_event(), 256u);
  r.w16(kAttr, kAttrOn | kAttrIrq);
  EXPECT_LE(r.sched.when(r.sched.find("spu.sample")) - r.sched.now(), Spu::kCyclesPerSample);
}

TEST(SpuLazy, CdPushTiedWithASampleKeepsTheEventOrder) {
  // An event booked at a sample's own time runs before that sample if it was registered before
  // the SPU's event, after it otherwise (Scheduler: ties by registration), batching or not. The
  // capture buffer at 0 holds each sample's CD left input before volume (psx-spx "SPU Memory
  // layout"), so sample k (due at k * 768, writing halfword k - 1) shows what it popped.
  for (u32 batch : {1u, Spu::kDefaultMaxBatch}) {
    Scheduler sched;
    InterruptController irq;
    AudioFifo cd;
    const Scheduler::Handle before = sched.add_event("push.before", [&](Cycles) { cd.push({111, 0}); });
    Spu spu(sched, irq, cd);
    const Scheduler::Handle after = sched.add_event("push.after", [&](Cycles) { cd.push({222, 0}); });
    spu.set_max_batch(batch);
    sched.schedule_at(before, 10 * Spu::kCyclesPerSample);
    sched.schedule_at(after, 20 * Spu::kCyclesPerSample);
    while (sched.now() < 30 * Spu::kCyclesPerSample) {
      sched.advance(1000);  // events run late, as after a long instruction
      if (sched.now() >= sched.next_deadline()) sched.run_due_events();
    }
    const u8* ram = spu.ram();
    auto cd_left = [&](u32 k) { return static_cast<s16>(ram[2 * (k - 1)] | ram[2 * (k - 1) + 1] << 8); };
    EXPECT_EQ(cd_left(9), 0) << batch;
    EXPECT_EQ(cd_left(10), 111) << batch;
    EXPECT_EQ(cd_left(11), 0) << batch;
    EXPECT_EQ(cd_left(20), 0) << batch;
    EXPECT_EQ(cd_left(21), 222) << batch;
  }
}

TEST(SpuLazy, SchedulerHorizonInsideAnEventIsItsTurn) {
  // psx-spx has nothing to say here: the rule is the scheduler's own order (earliest first, ties
  // by registration). Inside the callback of an event booked at 1000 that ran 50 cycles late, a
  // lower handle has had its turn at 1000, a higher one only up to 999; outside, the present.
  Scheduler s;
  Cycles low = 0, self = 0, high = 0;
  Scheduler::Handle a = s.add_event("a", [](Cycles) {});
  Scheduler::Handle b = s.add_event("b", [&](Cycles) {
    low = s.horizon(a);
    self = s.horizon(1);
    high = s.horizon(2);
  });
  s.add_event("c", [](Cycles) {});
  s.schedule(b, 1000);
  s.advance(1050);
  s.run_due_events();
  EXPECT_EQ(low, 1000u);
  EXPECT_EQ(self, 1000u);
  EXPECT_EQ(high, 999u);
  EXPECT_EQ(s.horizon(a), 1050u);
}

namespace {

// A guest loop waiting for SPUSTAT bit 11 to change (it flips every 256 samples as the capture
// buffers pass their halves, psx-spx "SPU Status Register"), counting the flips in s1 and summing
// root counter 2 (system clock) at each in s0, so that a flip seen late changes the state. MIPS I
// encodings from psx-spx "CPU Opcode Encoding".
constexpr u32 kT0 = 8, kT1 = 9, kT2 = 10, kT3 = 11, kS0 = 16, kS1 = 17;
u32 itype(u32 op, u32 rs, u32 rt, u32 imm) { return op << 26 | rs << 21 | rt << 16 | (imm & 0xFFFF); }
std::vector<u32> stat_flip_counter() {
  return {itype(0x0F, 0, kT0, 0x1F80),        // lui t0, 1F80h
          itype(0x09, 0, kT1, 0),             // addiu t1, zero, 0: bit 11 at power-on
          itype(0x25, kT0, kT2, 0x1DAE),      // lhu t2, 1DAEh(t0): SPUSTAT
          0,                                  // nop
          itype(0x0C, kT2, kT2, 0x800),       // andi t2, t2, 800h
          itype(0x04, kT2, kT1, u32(-4)),     // beq t2, t1, back to the lhu
          0,                                  // nop
          itype(0x09, kS1, kS1, 1),           // addiu s1, s1, 1
          itype(0x0D, kT2, kT1, 0),           // ori t1, t2, 0
          itype(0x25, kT0, kT3, 0x1120),      // lhu t3, 1120h(t0): timer 2 counter
          kS0 << 21 | kT3 << 16 | kS0 << 11 | 0x21,  // addu s0, s0, t3
          0x02u << 26 | ((0x80010008u >> 2) & 0x03FFFFFF),  // j the lhu
          0};
}

struct FlipRun {
  std::vector<u8> state;
  u64 skips;
  u32 flips;
  Cycles cycles, polled_from;
};

// `cycles_first` cycles spent first in a loop that reads nothing (j to itself), which idle
// skipping skips while the SPU's batches run past the flips, since nothing polls SPUSTAT yet.
FlipRun count_stat_flips(bool idle_skip, u32 max_batch, Cycles cycles_first = 0) {
  Console c;
  c.set_idle_skip(idle_skip);
  c.spu().set_max_batch(max_batch);
  const std::vector<u32> code = stat_flip_counter();
  for (u32 i = 0; i < code.size(); ++i) c.write32(0x80010000 + 4 * i, code[i]);
  if (cycles_first) {
    constexpr u32 kSpin = 0x80010100;
    c.write32(kSpin, 0x02u << 26 | ((kSpin >> 2) & 0x03FFFFFF));  // j kSpin
    c.write32(kSpin + 4, 0);                                      // nop
    c.cpu().set_pc(kSpin);
    c.run_cycles(cycles_first);
  }
  const Cycles polled_from = c.cycles();
  c.cpu().set_pc(0x80010000);
  c.run_frames(6);
  return {c.save_state(false), c.idle_skip_stats().skips, c.cpu().reg(kS1), c.cycles(), polled_from};
}

}  // namespace

TEST(SpuLazy, SpustatPollSkippedIdleSeesEveryFlipOnTime) {
  // Idle skipping takes SPUSTAT to change only at an event, so the loop's first examination has
  // the SPU end its batches at the flips (Spu::end_batches_at_flips). Batches of 1024 or 300
  // samples alone would run past them.
  for (u32 batch : {Spu::kDefaultMaxBatch, 300u}) {
    const FlipRun on = count_stat_flips(true, batch), off = count_stat_flips(false, batch);
    EXPECT_GT(on.skips, 0u);
    EXPECT_TRUE(on.state == off.state) << "state differs with idle skipping, batch " << batch;
    // One flip every 256 * 768 cycles from power-on (the loop sees each within a few cycles).
    EXPECT_EQ(on.flips, on.cycles / (256 * Spu::kCyclesPerSample)) << batch;
    EXPECT_EQ(on.flips, off.flips) << batch;
  }
}

TEST(SpuLazy, SpustatFirstPolledAfterLongBatchesSeesEveryFlipOnTime) {
  // The SPU has made 1024-sample batches for two frames and more when the loop starts polling,
  // past VBlank's end, so that the next event (the next VBlank) lies beyond the next flip: the
  // first examination must catch the SPU up, book that flip, and not skip towards the VBlank.
  constexpr Cycles kFirst = 1'200'000;
  const FlipRun on = count_stat_flips(true, Spu::kDefaultMaxBatch, kFirst);
  const FlipRun off = count_stat_flips(false, Spu::kDefaultMaxBatch, kFirst);
  EXPECT_GT(on.skips, 0u);
  EXPECT_TRUE(on.state == off.state) << "state differs with idle skipping";
  EXPECT_EQ(on.flips, off.flips);
  // Counted from a first compare with bit 11 at 0: the flips up to the end, less those before
  // polling began rounded down to an even number (bit 11 is back at 0 after each pair).
  constexpr Cycles kFlip = 256 * Spu::kCyclesPerSample;
  EXPECT_EQ(on.flips, on.cycles / kFlip - (on.polled_from / kFlip & ~Cycles{1}));
}

namespace {

std::vector<StereoSample> audio(Console& c) {
  std::vector<StereoSample> v;
  c.take_audio(v);
  return v;
}

bool same_audio(const std::vector<StereoSample>& a, const std::vector<StereoSample>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].left != b[i].left || a[i].right != b[i].right) return false;
  return true;
}

void tumble_batched_vs_per_sample(bool idle_skip) {
  tumble_test::TumbleConsole batched, per_sample;
  per_sample.console.spu().set_max_batch(1);
  for (auto* t : {&batched, &per_sample}) t->console.set_idle_skip(idle_skip);
  auto check = [&](const char* when) {
    ASSERT_EQ(batched.console.save_state(false), per_sample.console.save_state(false)) << when;
    std::vector<StereoSample> a = audio(batched.console), b = audio(per_sample.console);
    ASSERT_TRUE(same_audio(a, b)) << when;
    ASSERT_EQ(a.size(), b.size()) << when;
  };
  for (auto* t : {&batched, &per_sample}) t->console.run_frames(120);
  check("title");
  for (auto* t : {&batched, &per_sample}) tumble_test::play_level_one_moves(t->console);
  check("after the level-one moves");
}

}  // namespace

TEST(SpuLazy, TumbleTitleAndLevelSameWithBatchingIdleSkipOn) { tumble_batched_vs_per_sample(true); }
TEST(SpuLazy, TumbleTitleAndLevelSameWithBatchingIdleSkipOff) { tumble_batched_vs_per_sample(false); }

TEST(SpuLazy, StateSavedInTheMiddleOfABatchResumesExactly) {
  // Stop 100,001 cycles into a frame, in the middle of a batch, save, and go on both in the
  // console that saved and in a fresh one that loads the state; a console stepping every sample,
  // stopped at the same cycle, saves the same bytes.
  tumble_test::TumbleConsole a, per_sample, b;
  per_sample.console.spu().set_max_batch(1);
  for (auto* t : {&a, &per_sample}) {
    t->console.run_frames(150);
    t->console.run_cycles(100001);
  }
  Scheduler& s = a.console.scheduler();
  ASSERT_GT(s.when(s.find("spu.sample")), s.now() + Spu::kCyclesPerSample) << "not batching";
  const std::vector<u8> saved = a.console.save_state(false);
  ASSERT_EQ(saved, per_sample.console.save_state(false));
  audio(a.console);
  b.console.load_state(saved);
  for (auto* t : {&a, &b}) {
    t->console.run_frames(60);
    tumble_test::play_level_one_moves(t->console);
  }
  ASSERT_EQ(a.console.save_state(false), b.console.save_state(false));
  EXPECT_TRUE(same_audio(audio(a.console), audio(b.console)));
}
