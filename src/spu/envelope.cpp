// SPU envelope generators: the shared rate engine, ADSR phases and volume sweeps
// (psx-spx "SPU Volume and ADSR Generator").
#include "spu/envelope.h"

#include <algorithm>

namespace psx::spu {

namespace {

bool slow_high(s16 level, const EnvelopeParams& p) { return p.exponential && !p.decreasing && level > 0x6000; }

// The level a step of the rate engine makes from `level` (its counter having overflowed).
s16 stepped(s16 level, const EnvelopeParams& p, bool high) {
  s32 step = high ? p.step_high : p.step;
  if (p.exponential && p.decreasing) step = (step * level) >> 15;  // the step shrinks with the level
  return static_cast<s16>(std::clamp(level + step, p.min_level, p.max_level));
}

}  // namespace

s16 envelope_tick(u32& counter, s16 level, const EnvelopeParams& p) {
  const bool high = slow_high(level, p);
  counter += high ? p.increment_high : p.increment;
  if (!(counter & 0x8000)) return level;
  counter = 0;
  return stepped(level, p, high);
}

u32 envelope_wait(u32& counter, s16 level, const EnvelopeParams& p, u32 n) {
  const bool high = slow_high(level, p);
  const u32 increment = high ? p.increment_high : p.increment;
  if (increment == 0) {  // the all-ones rate: its counter stays below 8000h, it never steps
    return counter < 0x8000 ? n : 0;
  }
  if (counter >= 0x8000) return 0;  // only a loaded state holds such a counter: tick by tick
  // From below 8000h the tick that sets bit 15 is the k-th: counter + k * increment >= 8000h.
  const u32 k = (0x8000 - counter + increment - 1) / increment;
  if (n < k) {
    counter += n * increment;
    return n;
  }
  if (stepped(level, p, high) != level) {
    counter += (k - 1) * increment;
    return k - 1;
  }
  // A level held at its bound (or at 0 by an exponential decrease) stays there: only the counter
  // moves, back to 0 at each overflow, which then comes every `period` ticks.
  const u32 period = (0x8000 + increment - 1) / increment;
  counter = ((n - k) % period) * increment;
  return n;
}

EnvelopeParams Adsr::params() const {
  const u32 r = reg_;
  switch (phase_) {
    case Phase::Attack:  // ADSR1 bit 15 mode, bits 10-14 shift, bits 8-9 step; always increase
      return {static_cast<u8>((r >> 8) & 0x7F), 0x7F, false, ((r >> 15) & 1) != 0, false};
    case Phase::Decay:  // bits 4-7 shift, step fixed "-8", always exponential decrease
      return {static_cast<u8>(((r >> 4) & 0xF) << 2), 0x7C, true, true, false};
    case Phase::Sustain:  // ADSR2 bit 31 mode, bit 30 direction, bits 24-28 shift, 22-23 step
      return {static_cast<u8>((r >> 22) & 0x7F), 0x7F, ((r >> 30) & 1) != 0, ((r >> 31) & 1) != 0, false};
    case Phase::Release:  // bit 21 mode, bits 16-20 shift, step fixed "-8", always decrease
      return {static_cast<u8>(((r >> 16) & 0x1F) << 2), 0x7C, true, ((r >> 21) & 1) != 0, false};
    case Phase::Off:
      break;
  }
  return {};
}

void Adsr::start(Phase p) {
  phase_ = p;
  counter_ = 0;
  params_ = params();
}

void Adsr::key_on() {
  level_ = 0;
  start(Phase::Attack);
}

void Adsr::key_off() {
  if (phase_ != Phase::Off) start(Phase::Release);
}

void Adsr::force_off() {
  level_ = 0;
  start(Phase::Off);
}

void Adsr::step() {
  level_ = envelope_tick(counter_, level_, params_);
  if (!phase_ends()) return;
  switch (phase_) {
    case Phase::Attack: return start(Phase::Decay);
    case Phase::Decay: return start(Phase::Sustain);
    case Phase::Release: return force_off();
    case Phase::Sustain:
    case Phase::Off: return;
  }
}

bool Adsr::phase_ends() const {
  switch (phase_) {
    case Phase::Attack: return level_ >= 0x7FFF;
    case Phase::Decay: return level_ <= sustain_target();
    case Phase::Release: return level_ <= 0;
    case Phase::Sustain:  // lasts until key off
    case Phase::Off: break;
  }
  return false;
}

void Adsr::ticks(u32 n) {
  while (n > 0 && phase_ != Phase::Off) {
    // A level already past the phase's end (key off at 0, a written ENVX) ends it at the next tick.
    if (!phase_ends()) {
      n -= envelope_wait(counter_, level_, params_, n);
      if (n == 0) return;
    }
    step();  // the tick that steps the level or ends the phase
    --n;
  }
}

void Adsr::do_state(StateIO& s) {
  s.pod(reg_);
  s.pod(phase_);
  s.pod(level_);
  s.pod(counter_);
  if (s.loading() && static_cast<u8>(phase_) > static_cast<u8>(Phase::Release)) s.fail("bad ADSR phase");
  if (s.loading()) params_ = params();
}

namespace {

// Sweep mode: bit 14 exponential, bit 13 decrease, bit 12 phase, bits 0-6 shift:step.
EnvelopeParams sweep_params(u16 reg) {
  return {static_cast<u8>(reg & 0x7F), 0x7F, ((reg >> 13) & 1) != 0, ((reg >> 14) & 1) != 0, ((reg >> 12) & 1) != 0};
}

}  // namespace

void VolumeSweep::write(u16 value) {
  reg_ = value;
  counter_ = 0;
  params_ = sweep_params(value);
}

void VolumeSweep::ticks(u32 n) {
  if (n == 0) return;
  if (!(reg_ & 0x8000)) {
    tick();
    return;
  }
  while (n > 0) {
    n -= envelope_wait(counter_, level_, params_, n);
    if (n == 0) return;
    level_ = envelope_tick(counter_, level_, params_);
    --n;
  }
}

void VolumeSweep::do_state(StateIO& s) {
  s.pod(reg_);
  s.pod(level_);
  s.pod(counter_);
  if (s.loading()) params_ = sweep_params(reg_);
}

}  // namespace psx::spu
