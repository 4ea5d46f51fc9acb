// The SPU noise generator (psx-spx "SPU Noise Generator"): one shared 16-bit shift register,
// clocked at a rate set by ATTR bits 8-13, replaces the ADPCM sample of voices with NON set.
#pragma once
#include "core/state.h"
#include "core/types.h"

namespace psx::spu {

class NoiseGenerator {
 public:
  // One 44.1 kHz tick; `attr` is the ATTR (SPUCNT) register.
  void tick(u16 attr) {
    const s32 step = 4 + ((attr >> 8) & 3);
    const s32 shift = (attr >> 10) & 0xF;
    timer_ -= step;
    const u32 l = static_cast<u16>(level_);
    const u32 parity = ((l >> 15) ^ (l >> 12) ^ (l >> 11) ^ (l >> 10) ^ 1) & 1;
    if (timer_ < 0) level_ = static_cast<s16>((l << 1) | parity);
    // The timer is reloaded at most twice per tick.
    if (timer_ < 0) timer_ += 0x20000 >> shift;
    if (timer_ < 0) timer_ += 0x20000 >> shift;
  }
  // n ticks at once: from one timer underflow to the next instead of tick by tick.
  void ticks(u16 attr, u32 n) {
    const s32 step = 4 + ((attr >> 8) & 3);
    while (n > 0) {
      if (timer_ < 0) {  // only from a loaded state: a tick leaves the timer at 0 or more
        tick(attr);
        --n;
        continue;
      }
      // The tick that takes the timer below 0 is the (timer / step + 1)th.
      const u32 to_underflow = static_cast<u32>(timer_ / step) + 1;
      if (to_underflow > n) {
        timer_ -= static_cast<s32>(n) * step;
        return;
      }
      timer_ -= static_cast<s32>(to_underflow - 1) * step;
      tick(attr);
      n -= to_underflow;
    }
  }
  s16 level() const { return level_; }

  void do_state(StateIO& s) {
    s.pod(level_);
    s.pod(timer_);
  }

 private:
  s16 level_ = 0;
  s32 timer_ = 0;
};

}  // namespace psx::spu
