// ADSR envelope and volume sweep values at chosen sample counts, worked by hand from psx-spx
// "Envelope Operation depending on Shift/Step/Mode/Direction": step = (7 - StepValue), negated
// (NOT) when decreasing, shifted left by max(0, 11 - shift); the step applies every
// 1 << max(0, shift - 11) samples; exponential decrease scales the step by level/8000h;
// exponential increase above 6000h slows down.
#include <gtest/gtest.h>

#include <algorithm>

#include "spu/envelope.h"
#include "spu/noise.h"

using namespace psx;
using namespace psx::spu;

namespace {
// ADSR1 (low half) and ADSR2 (high half) fields, psx-spx bit positions.
u32 adsr(u32 attack_exp, u32 attack_shift, u32 attack_step, u32 decay_shift, u32 sustain_level, u32 sustain_exp,
         u32 sustain_dec, u32 sustain_shift, u32 sustain_step, u32 release_exp, u32 release_shift) {
  u32 lo = attack_exp << 15 | attack_shift << 10 | attack_step << 8 | decay_shift << 4 | sustain_level;
  u32 hi = sustain_exp << 15 | sustain_dec << 14 | sustain_shift << 8 | sustain_step << 6 | release_exp << 5 |
           release_shift;
  return lo | hi << 16;
}
void ticks(Adsr& a, int n) {
  for (int i = 0; i < n; ++i) a.tick();
}
}  // namespace

TEST(SpuEnvelope, FastLinearAttackThenExponentialDecayToSustain) {
  Adsr a;
  // Attack shift 0 step 0: +7 << 11 = +14336 every sample. Decay shift 0: -8 << 11 = -16384
  // scaled by level/32768. Sustain level 3: (3+1)*800h = 8192.
  a.set_register(adsr(0, 0, 0, 0, 3, 0, 0, 31, 3, 0, 0));
  a.key_on();
  EXPECT_EQ(a.level(), 0);
  a.tick();
  EXPECT_EQ(a.level(), 14336);
  a.tick();
  EXPECT_EQ(a.level(), 28672);
  a.tick();
  EXPECT_EQ(a.level(), 32767);  // 43008 saturates at 7FFFh, attack ends
  EXPECT_EQ(a.phase(), Adsr::Phase::Decay);
  a.tick();
  EXPECT_EQ(a.level(), 16383);  // 32767 + (-16384*32767 >> 15) = 32767 - 16384
  a.tick();
  EXPECT_EQ(a.level(), 8191);  // 16383 + (-16384*16383 >> 15) = 16383 - 8192
  EXPECT_EQ(a.phase(), Adsr::Phase::Sustain);  // 8191 <= 8192
  ticks(a, 100000);  // sustain shift 31 step 3 is the all-ones rate: it never steps
  EXPECT_EQ(a.level(), 8191);
}

TEST(SpuEnvelope, SlowAttackStepsEveryFewSamples) {
  Adsr a;
  // Attack shift 12, step 1: +6 every 1 << (12-11) = 2 samples.
  a.set_register(adsr(0, 12, 1, 0, 15, 0, 0, 0, 0, 0, 0));
  a.key_on();
  ticks(a, 1);
  EXPECT_EQ(a.level(), 0);
  ticks(a, 1);
  EXPECT_EQ(a.level(), 6);
  ticks(a, 98);
  EXPECT_EQ(a.level(), 300);  // 100 samples = 50 steps of 6
  // Shift 15: one step of +6 every 16 samples.
  a.set_register(adsr(0, 15, 1, 0, 15, 0, 0, 0, 0, 0, 0));
  a.key_on();
  ticks(a, 15);
  EXPECT_EQ(a.level(), 0);
  ticks(a, 1);
  EXPECT_EQ(a.level(), 6);
}

TEST(SpuEnvelope, ExponentialAttackSlowsAbove6000h) {
  Adsr a;
  // Attack shift 8, step 0: +7 << 3 = +56 per sample; exponential: above 6000h (24576) the
  // step is divided by 4 (shift < 10) = +14.
  a.set_register(adsr(1, 8, 0, 0, 15, 0, 0, 0, 0, 0, 0));
  a.key_on();
  ticks(a, 439);
  EXPECT_EQ(a.level(), 439 * 56);  // 24584: just over 6000h
  a.tick();
  EXPECT_EQ(a.level(), 24584 + 14);
}

TEST(SpuEnvelope, LinearReleaseAndOff) {
  Adsr a;
  // Release shift 13: -8 every 1 << 2 = 4 samples.
  a.set_register(adsr(0, 0, 0, 0, 15, 0, 0, 31, 3, 0, 13));
  a.key_on();
  ticks(a, 3);
  ASSERT_EQ(a.level(), 32767);
  a.key_off();
  EXPECT_EQ(a.phase(), Adsr::Phase::Release);
  ticks(a, 3);
  EXPECT_EQ(a.level(), 32767);
  ticks(a, 1);
  EXPECT_EQ(a.level(), 32759);
  ticks(a, 400);
  EXPECT_EQ(a.level(), 32759 - 800);  // 100 more steps
  // Release shift 0 linear: -16384 per sample: 32767 -> 16383 -> 0 and off.
  a.set_register(adsr(0, 0, 0, 0, 15, 0, 0, 31, 3, 0, 0));
  a.key_on();
  ticks(a, 3);
  a.key_off();
  ticks(a, 1);
  EXPECT_EQ(a.level(), 16383);
  ticks(a, 1);
  EXPECT_EQ(a.level(), 0);
  EXPECT_EQ(a.phase(), Adsr::Phase::Off);
}

TEST(SpuEnvelope, ExponentialReleaseHalvesAtShiftZero) {
  Adsr a;
  a.set_register(adsr(0, 0, 0, 0, 15, 0, 0, 31, 3, 1, 0));
  a.key_on();
  ticks(a, 3);
  a.key_off();
  ticks(a, 1);
  EXPECT_EQ(a.level(), 16383);  // 32767 + (-16384*32767 >> 15)
  ticks(a, 1);
  EXPECT_EQ(a.level(), 8191);  // 16383 + (-16384*16383 >> 15)
  ticks(a, 1);
  EXPECT_EQ(a.level(), 4095);
}

TEST(SpuEnvelope, SlowestRatesWait32768Samples) {
  // Sustain increase, shift 26 step 2 (rate 6Ah): +5 once every 8000h samples. psx-spx: rate
  // 76h (shift 29 step 2) behaves the same.
  for (u32 shift : {26u, 29u}) {
    u32 counter = 0;
    EnvelopeParams p{static_cast<u8>(shift << 2 | 2), 0x7F, false, false, false};
    s16 level = 1000;
    for (int i = 0; i < 32767; ++i) level = envelope_tick(counter, level, p);
    EXPECT_EQ(level, 1000) << shift;
    level = envelope_tick(counter, level, p);
    EXPECT_EQ(level, 1005) << shift;
  }
}

// The rate engine written out plainly, rule by rule as psx-spx states them, for comparison with
// envelope_tick(), which works its step and increment out once per phase.
s16 documented_tick(u32& counter, s16 level, u32 rate, u32 rate_mask, bool decreasing, bool exponential,
                    bool phase_negative) {
  const s32 shift = static_cast<s32>(rate >> 2);
  s32 step = 7 - static_cast<s32>(rate & 3);
  if (decreasing != phase_negative || (exponential && decreasing)) step = -step - 1;  // NOT
  if (shift < 11) step *= 1 << (11 - shift);
  u32 increment = shift > 11 ? 0x8000u >> (shift - 11) : 0x8000u;  // "every 1 << (shift-11) samples"
  if (exponential && !decreasing && level > 0x6000) {
    // Four times slower above 6000h: a quarter of the step, the increment, or half of each.
    if (shift < 10) step /= 4;
    else if (shift == 10) step /= 2, increment /= 2;
    else increment /= 4;
  } else if (exponential && decreasing) {
    step = (step * level) >> 15;
  }
  if ((rate & rate_mask) != rate_mask && increment == 0) increment = 1;
  counter += increment;
  if (counter < 0x8000) return level;
  counter = 0;
  const s32 lo = decreasing && !phase_negative ? 0 : -0x8000, hi = decreasing && phase_negative ? 0 : 0x7FFF;
  return static_cast<s16>(std::clamp(level + step, lo, hi));
}

TEST(SpuEnvelope, EveryRateAndModeFollowsTheDocumentedEngine) {
  const s16 levels[] = {-0x8000, -0x6001, -1, 0, 1, 0x100, 0x5FFF, 0x6000, 0x6001, 0x7000, 0x7FFF};
  const u32 counters[] = {0, 1, 0x3FFF, 0x7FFE, 0x7FFF};
  int compared = 0;
  for (u32 rate = 0; rate < 0x80; ++rate)
    for (u32 mask : {0x7Fu, 0x7Cu})
      for (u32 mode = 0; mode < 8; ++mode) {
        const bool dec = mode & 1, exp = mode & 2, neg = mode & 4;
        const EnvelopeParams p(static_cast<u8>(rate), static_cast<u8>(mask), dec, exp, neg);
        for (s16 level : levels)
          for (u32 counter : counters) {
            u32 got_counter = counter, want_counter = counter;
            const s16 got = envelope_tick(got_counter, level, p);
            const s16 want = documented_tick(want_counter, level, rate, mask, dec, exp, neg);
            ASSERT_EQ(got, want) << "rate " << rate << " mode " << mode << " level " << level << " counter " << counter;
            ASSERT_EQ(got_counter, want_counter) << "rate " << rate << " mode " << mode << " level " << level;
            ++compared;
          }
      }
  EXPECT_EQ(compared, 128 * 2 * 8 * 11 * 5);
}

TEST(SpuEnvelope, VolumeSweeps) {
  VolumeSweep v;
  // Fixed volume 2000h is volume/2: level 4000h, latched on the next tick.
  v.write(0x2000);
  EXPECT_EQ(v.level(), 0);
  v.tick();
  EXPECT_EQ(v.level(), 0x4000);
  // Linear increase, shift 0 step 0: +14336 per sample up to 7FFFh.
  v.write(0x8000);
  v.tick();
  EXPECT_EQ(v.level(), 0x4000 + 14336);
  v.tick();
  EXPECT_EQ(v.level(), 32767);
  // Linear decrease (bit 13), shift 11 step 3: -5 per sample, floored at 0.
  v.write(0x8000 | 1 << 13 | 11 << 2 | 3);
  v.tick();
  EXPECT_EQ(v.level(), 32762);
  // Decrease with negative phase (bit 12): "decreasing XOR phase" is false, so the step is +7
  // (shift 11 step 0), and the level is clamped to -8000h..0.
  v.set_level(-100);
  v.write(0x8000 | 1 << 13 | 1 << 12 | 11 << 2 | 0);
  v.tick();
  EXPECT_EQ(v.level(), -93);
  for (int i = 0; i < 20; ++i) v.tick();
  EXPECT_EQ(v.level(), 0);
}

TEST(SpuEnvelope, BatchedTicksWorkedByHand) {
  // Attack shift 12 step 1: +6 on every 2nd sample, so 1001 samples step 500 times; the 5462nd
  // step (32767 / 6 = 5461.2) saturates at 7FFFh and starts Decay.
  Adsr a;
  a.set_register(adsr(0, 12, 1, 15, 15, 0, 0, 31, 3, 0, 0));
  a.key_on();
  a.ticks(1001);
  EXPECT_EQ(a.level(), 3000);
  EXPECT_EQ(a.phase(), Adsr::Phase::Attack);
  a.ticks(2 * 5462 - 1002);
  EXPECT_EQ(a.level(), 32766);  // 5461 steps
  a.ticks(1);
  EXPECT_EQ(a.level(), 32767);
  EXPECT_EQ(a.phase(), Adsr::Phase::Decay);
  // Sustain level 15 is (15+1)*800h = 8000h: the level is already at or below it, so the next
  // tick ends Decay without a step (decay shift 15 steps every 16th sample).
  a.ticks(1);
  EXPECT_EQ(a.level(), 32767);
  EXPECT_EQ(a.phase(), Adsr::Phase::Sustain);
  // A sweep at shift 26 step 2 adds 5 once every 8000h samples.
  VolumeSweep v;
  v.write(0x8000 | 26 << 2 | 2);
  v.ticks(32767);
  EXPECT_EQ(v.level(), 0);
  v.ticks(1);
  EXPECT_EQ(v.level(), 5);
  v.ticks(3 * 32768);
  EXPECT_EQ(v.level(), 20);
  // Linear decrease at shift 13 step 3: -5 on every 4th sample (counter += 2000h). From 12 the
  // steps at samples 4, 8 and 12 give 7, 2 and 0, where the level stays; the counter goes on:
  // 2000h at 13, 4000h at 14, so after a write of ENVX-like level 100 at sample 14 the next step
  // comes at sample 16, not 18.
  v.set_level(12);
  v.write(0x8000 | 1 << 13 | 13 << 2 | 3);
  v.ticks(8);
  EXPECT_EQ(v.level(), 2);
  v.ticks(6);
  EXPECT_EQ(v.level(), 0);
  v.set_level(100);
  v.ticks(1);
  EXPECT_EQ(v.level(), 100);
  v.ticks(1);
  EXPECT_EQ(v.level(), 95);
  // Held at 0 for 1,000,001 samples from counter 0 (1,000,001 = 4 * 250,000 + 1): the counter
  // ends at 2000h, so the step after a new level comes 3 samples later.
  v.set_level(0);
  v.ticks(1000001);
  v.set_level(100);
  v.ticks(2);
  EXPECT_EQ(v.level(), 100);
  v.ticks(1);
  EXPECT_EQ(v.level(), 95);
}

TEST(SpuEnvelope, BatchedTicksMatchTickByTick) {
  // Pseudo-random ADSR registers and sweeps, from key on and part-way, over stretches of 1 to
  // 70000 samples (past the slowest rate's wait), compared field by field through their states.
  u32 lcg = 12345;
  const auto next = [&lcg] { return lcg = lcg * 1664525u + 1013904223u; };
  for (int trial = 0; trial < 400; ++trial) {
    Adsr one, batch;
    const u32 reg = next();
    one.set_register(reg), batch.set_register(reg);
    one.key_on(), batch.key_on();
    VolumeSweep v_one, v_batch;
    const u16 sweep = static_cast<u16>(next() | 0x8000);
    v_one.write(sweep), v_batch.write(sweep);
    for (u32 n : {1u, 3u, 64u, 1000u, 70000u, 5u, 4097u}) {
      if (n == 5 && trial % 2) one.key_off(), batch.key_off();
      for (u32 k = 0; k < n; ++k) one.tick(), v_one.tick();
      batch.ticks(n);
      v_batch.ticks(n);
      StateIO a, b;
      one.do_state(a), v_one.do_state(a);
      batch.do_state(b), v_batch.do_state(b);
      ASSERT_EQ(a.buffer(), b.buffer()) << "ADSR " << std::hex << reg << " sweep " << sweep << std::dec << " n " << n;
    }
  }
}

TEST(SpuNoise, ShiftRegisterSequence) {
  // Shift 15, step 3 (step 7): timer -7 each sample, reload +4 (20000h >> 15) up to twice, so
  // the register shifts every sample; parity of bits 15,12,11,10 XOR 1 enters at bit 0.
  NoiseGenerator n;
  const u16 attr = 15 << 10 | 3 << 8;
  u32 expect = 0;
  for (int i = 1; i <= 11; ++i) {
    n.tick(attr);
    expect = (expect << 1) | 1;  // bits 10..15 still clear: parity 1
    EXPECT_EQ(static_cast<u16>(n.level()), expect) << i;
  }
  n.tick(attr);  // 7FFh has bit 10 set: parity 0
  EXPECT_EQ(static_cast<u16>(n.level()), 0xFFEu);

  // Shift 0, step 0 (step 4): first sample shifts (timer -4) and reloads 20000h; the next
  // shift comes when 4*(k-1) > 131068, at sample 32769.
  NoiseGenerator slow;
  slow.tick(0);
  EXPECT_EQ(slow.level(), 1);
  for (int k = 2; k <= 32768; ++k) slow.tick(0);
  EXPECT_EQ(slow.level(), 1);
  slow.tick(0);
  EXPECT_EQ(slow.level(), 3);
}

TEST(SpuNoise, BatchedTicksMatchTickByTick) {
  // Every noise clock (ATTR bits 8-13), from the start and from states part-way through, over
  // stretches of 1 to 5000 samples.
  for (u32 clock = 0; clock < 64; ++clock) {
    const u16 attr = static_cast<u16>(clock << 8);
    NoiseGenerator one, batch;
    for (u32 n : {1u, 2u, 7u, 100u, 5000u, 3u, 1234u}) {
      for (u32 k = 0; k < n; ++k) one.tick(attr);
      batch.ticks(attr, n);
      ASSERT_EQ(one.level(), batch.level()) << "clock " << clock << " n " << n;
      StateIO a, b;
      one.do_state(a);
      batch.do_state(b);
      ASSERT_EQ(a.buffer(), b.buffer()) << "clock " << clock << " n " << n;
    }
  }
  // A state may hold a timer below 0 (do_state loads it as it is): the first tick reloads it.
  for (s32 timer : {-1, -7, -100, -0x20000}) {
    NoiseGenerator one, batch;
    StateIO saved;
    s16 level = 0x1234;
    saved.pod(level);
    saved.pod(timer);
    for (NoiseGenerator* g : {&one, &batch}) {
      StateIO load(saved.buffer().data(), saved.buffer().size());
      g->do_state(load);
    }
    for (u32 k = 0; k < 300; ++k) one.tick(0x3F00);
    batch.ticks(0x3F00, 300);
    StateIO a, b;
    one.do_state(a);
    batch.do_state(b);
    ASSERT_EQ(a.buffer(), b.buffer()) << "timer " << timer;
  }
}
