// SPU envelope generators: the shared rate engine, ADSR phases and volume sweeps
// (psx-spx "SPU Volume and ADSR Generator").
#include "spu/envelope.h"

#include <algorithm>

namespace psx::spu {

s16 envelope_tick(u32& counter, s16 level, const EnvelopeParams& p) {
  const s32 shift = p.rate >> 2;
  const s32 step_value = p.rate & 3;
  // +7,+6,+5,+4, inverted to -8,-7,-6,-5 when decreasing (or when the phase bit flips an
  // increase). Exponential decrease always steps downwards: its phase bit has no effect.
  s32 step = 7 - step_value;
  if ((p.decreasing != p.phase_negative) || (p.exponential && p.decreasing)) step = ~step;
  step *= 1 << std::max<s32>(0, 11 - shift);
  u32 increment = 0x8000u >> std::max<s32>(0, shift - 11);

  if (p.exponential && !p.decreasing && level > 0x6000) {
    // "Exponential" increase is a slower linear increase above 6000h.
    if (shift < 10) {
      step >>= 2;
    } else if (shift >= 11) {
      increment >>= 2;
    } else {
      step >>= 1;
      increment >>= 1;
    }
  } else if (p.exponential && p.decreasing) {
    step = (step * level) >> 15;
  }
  if ((p.rate & p.rate_mask) != p.rate_mask) increment = std::max<u32>(increment, 1);

  counter += increment;
  if (!(counter & 0x8000)) return level;
  counter = 0;

  s32 next = level + step;
  if (!p.decreasing)
    next = std::clamp(next, -0x8000, 0x7FFF);
  else if (p.phase_negative)
    next = std::clamp(next, -0x8000, 0);
  else
    next = std::clamp(next, 0, 0x7FFF);
  return static_cast<s16>(next);
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

void VolumeSweep::write(u16 value) {
  reg_ = value;
  counter_ = 0;
}

void VolumeSweep::sweep() {
  // Sweep mode: bit 14 exponential, bit 13 decrease, bit 12 phase, bits 0-6 shift:step.
  const EnvelopeParams p{static_cast<u8>(reg_ & 0x7F), 0x7F, ((reg_ >> 13) & 1) != 0, ((reg_ >> 14) & 1) != 0,
                         ((reg_ >> 12) & 1) != 0};
  level_ = envelope_tick(counter_, level_, p);
}

void VolumeSweep::do_state(StateIO& s) {
  s.pod(reg_);
  s.pod(level_);
  s.pod(counter_);
}

}  // namespace psx::spu
