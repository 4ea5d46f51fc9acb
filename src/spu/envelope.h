// SPU envelope generators (psx-spx "SPU Volume and ADSR Generator"): the rate engine shared by
// every envelope ("Envelope Operation depending on Shift/Step/Mode/Direction"), the four-phase
// ADSR of each voice (ADSR1/ADSR2, ENVX) and the volume sweeps of the voice and main volumes.
#pragma once
#include "core/state.h"
#include "core/types.h"

namespace psx::spu {

// One envelope phase. `rate` is the 7-bit Shift:Step pair (shift in bits 2-6, step in bits 0-1).
// The constructor works out the rate engine's step and counter increment once per phase, not
// once per sample: most samples only add the increment to the counter.
struct EnvelopeParams {
  constexpr EnvelopeParams() : EnvelopeParams(0, 0x7F, false, false, false) {}
  constexpr EnvelopeParams(u8 rate, u8 rate_mask, bool decreasing, bool exponential, bool phase_negative);

  u8 rate = 0;
  // Rate bits that, all set, freeze the envelope (psx-spx: "all-ones never steps"): 7Fh for
  // attack/sustain/sweeps; decay and release have no step field, so only their shift counts (7Ch).
  u8 rate_mask = 0x7F;
  bool decreasing = false;
  bool exponential = false;
  bool phase_negative = false;
  // Derived: the step added when the counter overflows and the counter increment, below and above
  // 6000h (where an exponential increase slows down); and the clamp range of the level.
  s32 step = 0, step_high = 0;
  u32 increment = 0, increment_high = 0;
  s32 min_level = 0, max_level = 0;
};

constexpr EnvelopeParams::EnvelopeParams(u8 rate_, u8 rate_mask_, bool decreasing_, bool exponential_,
                                         bool phase_negative_)
    : rate(rate_), rate_mask(rate_mask_), decreasing(decreasing_), exponential(exponential_),
      phase_negative(phase_negative_) {
  // psx-spx "Envelope Operation depending on Shift/Step/Mode/Direction".
  const s32 shift = rate >> 2;
  // +7,+6,+5,+4, inverted to -8,-7,-6,-5 when decreasing (or when the phase bit flips an
  // increase). Exponential decrease always steps downwards: its phase bit has no effect.
  s32 base = 7 - (rate & 3);
  if ((decreasing != phase_negative) || (exponential && decreasing)) base = ~base;
  step = base * (1 << (shift < 11 ? 11 - shift : 0));
  increment = 0x8000u >> (shift > 11 ? shift - 11 : 0);
  // "Exponential" increase is a slower linear increase above 6000h.
  step_high = step, increment_high = increment;
  if (shift < 10) {
    step_high >>= 2;
  } else if (shift >= 11) {
    increment_high >>= 2;
  } else {
    step_high >>= 1;
    increment_high >>= 1;
  }
  // Only the all-ones rate never steps; every other one counts at least 1 per sample.
  if ((rate & rate_mask) != rate_mask) {
    if (increment == 0) increment = 1;
    if (increment_high == 0) increment_high = 1;
  }
  min_level = decreasing ? (phase_negative ? -0x8000 : 0) : -0x8000;
  max_level = decreasing && phase_negative ? 0 : 0x7FFF;
}

// Advances an envelope by one 44.1 kHz tick. `counter` is the phase's step counter (zeroed when
// a phase starts); returns the new level.
s16 envelope_tick(u32& counter, s16 level, const EnvelopeParams& p);
// Advances `counter` over as many of the next `n` ticks as leave the level alone (the ticks
// before the one that steps it, during which the rate is constant, or all n where a step would
// keep the level, held at its bound): what that many calls to envelope_tick() do. Returns how
// many it took; fewer than n means the next tick changes the level.
u32 envelope_wait(u32& counter, s16 level, const EnvelopeParams& p, u32 n);

// The ADSR envelope of one voice (ADSR1 = low half, ADSR2 = high half of the 32-bit value).
class Adsr {
 public:
  enum class Phase : u8 { Off, Attack, Decay, Sustain, Release };

  void set_register(u32 value) {
    reg_ = value;
    params_ = params();
  }
  u32 reg() const { return reg_; }

  // Key on starts Attack from level 0; key off starts Release from wherever the level is.
  void key_on();
  void key_off();
  // An End+Mute ADPCM block (flags End without Repeat) silences the voice at once.
  void force_off();
  // Once per sample for every voice; an Off envelope stays at its level.
  void tick() {
    if (phase_ != Phase::Off) step();
  }
  // n ticks, waiting steps counted at once (envelope_wait).
  void ticks(u32 n);

  s16 level() const { return level_; }
  // ENVX is writable; the next step continues from the written level.
  void set_level(s16 v) { level_ = v; }
  Phase phase() const { return phase_; }
  // Sustain level: (N+1)*800h (psx-spx ADSR1 bits 0-3).
  s32 sustain_target() const { return static_cast<s32>((reg_ & 0xF) + 1) * 0x800; }
  EnvelopeParams params() const;

  void do_state(StateIO& s);

 private:
  void start(Phase p);
  void step();
  // Whether the level ends the phase (Attack at 7FFFh, Decay at the sustain level, Release at 0).
  bool phase_ends() const;

  u32 reg_ = 0;
  Phase phase_ = Phase::Off;
  s16 level_ = 0;
  u32 counter_ = 0;
  EnvelopeParams params_;  // params() of the current phase and register, kept up to date
};

// A volume register (VOLL/VOLR, MVOLL/MVOLR): fixed volume (bit 15 = 0) or a sweep envelope.
class VolumeSweep {
 public:
  void write(u16 value);
  u16 reg() const { return reg_; }
  // Once per 44.1 kHz tick. A fixed volume is latched here, not on the register write (psx-spx:
  // "the Bit15=0 setting isn't applied until the next 44.1kHz cycle").
  void tick() {
    if (reg_ & 0x8000)
      level_ = envelope_tick(counter_, level_, params_);
    else
      level_ = static_cast<s16>(reg_ << 1);  // bits 0-14 are volume/2, a signed 15-bit number
  }
  // n ticks, waiting steps counted at once (envelope_wait).
  void ticks(u32 n);
  s16 level() const { return level_; }
  void set_level(s16 v) { level_ = v; }
  // A fixed volume already latched: tick() changes nothing.
  bool latched() const { return !(reg_ & 0x8000) && level_ == static_cast<s16>(reg_ << 1); }

  void do_state(StateIO& s);

 private:
  u16 reg_ = 0;
  s16 level_ = 0;
  u32 counter_ = 0;
  EnvelopeParams params_;  // the sweep's, from reg_ (used while bit 15 is set)
};

}  // namespace psx::spu
