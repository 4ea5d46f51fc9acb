// The baud-rate timer both serial ports show in SIO#_STAT bits 11 and up (psx-spx "Serial
// Interfaces (SIO)"): it reloads with BAUD * factor / 2, the factor picked by SIO#_MODE bits 0-1
// (STOP and MUL1 count as 1, MUL16, MUL64), and counts down at the CPU clock.
#pragma once
#include <algorithm>

#include "core/state.h"
#include "core/types.h"

namespace psx {

inline Cycles sio_baud_half_period(u16 baud, u16 mode) {
  static constexpr Cycles kFactor[4] = {1, 1, 16, 64};
  return std::max<Cycles>(baud * kFactor[mode & 3] / 2, 1);
}

// The timer of one port: when BAUD was last written, and the start of the count the latest read
// fell in. Programs poll SIO#_STAT in loops a few dozen cycles apart, so a read steps on from the
// previous one by the few half periods between instead of dividing all the time since BAUD was
// written (a 64-bit division: about 1% of Tumble's time, which polls the pad). The phase is
// derived, not saved: every count start gives the same bits.
class BaudTimer {
 public:
  void reload(Cycles now) {
    reload_at_ = now;
    forget_phase();
  }
  // The timer's value at `now`, placed at bits 11-31 of SIO#_STAT.
  u32 stat_bits(u16 baud, u16 mode, Cycles now) const {
    const Cycles half = sio_baud_half_period(baud, mode);
    if (half != phase_half_ || now < phase_at_) {  // BAUD or the factor changed, or time went back
      phase_at_ = reload_at_;
      phase_half_ = half;
    }
    Cycles elapsed = now - phase_at_;
    for (int i = 0; i < 4 && elapsed >= half; ++i) elapsed -= half, phase_at_ += half;
    if (elapsed >= half) {
      const Cycles whole = elapsed - elapsed % half;
      elapsed -= whole;
      phase_at_ += whole;
    }
    return static_cast<u32>((half - elapsed) & 0x1FFFFF) << 11;
  }
  void do_state(StateIO& s) {
    s.pod(reload_at_);
    if (s.loading()) forget_phase();
  }

 private:
  void forget_phase() {
    phase_at_ = reload_at_;
    phase_half_ = 0;
  }
  Cycles reload_at_ = 0;
  mutable Cycles phase_at_ = 0, phase_half_ = 0;
};

}  // namespace psx
