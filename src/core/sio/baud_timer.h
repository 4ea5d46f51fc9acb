// The baud-rate timer both serial ports show in SIO#_STAT bits 11 and up (psx-spx "Serial
// Interfaces (SIO)"): it reloads with BAUD * factor / 2, the factor picked by SIO#_MODE bits 0-1
// (STOP and MUL1 count as 1, MUL16, MUL64), and counts down at the CPU clock.
#pragma once
#include <algorithm>

#include "core/types.h"

namespace psx {

inline Cycles sio_baud_half_period(u16 baud, u16 mode) {
  static constexpr Cycles kFactor[4] = {1, 1, 16, 64};
  return std::max<Cycles>(baud * kFactor[mode & 3] / 2, 1);
}

// The timer's value `elapsed` cycles after BAUD was written, placed at bits 11-31 of SIO#_STAT.
inline u32 sio_baud_timer_bits(u16 baud, u16 mode, Cycles elapsed) {
  const Cycles half = sio_baud_half_period(baud, mode);
  return static_cast<u32>((half - elapsed % half) & 0x1FFFFF) << 11;
}

}  // namespace psx
