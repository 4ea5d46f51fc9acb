// SPU envelope generators: the shared rate engine, ADSR phases and volume sweeps
// (psx-spx "SPU Volume and ADSR Generator").
#include "spu/envelope.h"

#include <algorithm>

namespace psx::spu {

s16 envelope_tick(u32& counter, s16 level, const EnvelopeParams& p) {
  const bool high = p.exponential && !p.decreasing && level > 0x6000;
  counter += high ? p.increment_high : p.increment;
  if (!(counter & 0x8000)) return level;
  counter = 0;
  s32 step = high ? p.step_high : p.step;
  if (p.exponential && p.decreasing) step = (step * level) >> 15;  // the step shrinks with the level
  return static_cast<s16>(std::clamp(level + step, p.min_level, p.max_level));
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
  switch (phase_) {
    case Phase::Attack:
      if (level_ >= 0x7FFF) start(Phase::Decay);
      break;
    case Phase::Decay:
      if (level_ <= sustain_target()) start(Phase::Sustain);
      break;
    case Phase::Release:
      if (level_ <= 0) force_off();
      break;
    case Phase::Sustain:  // lasts until key off
    case Phase::Off:
      break;
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

void VolumeSweep::do_state(StateIO& s) {
  s.pod(reg_);
  s.pod(level_);
  s.pod(counter_);
  if (s.loading()) params_ = sweep_params(reg_);
}

}  // namespace psx::spu
