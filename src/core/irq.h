// Interrupt controller: I_STAT (0x1F801070) and I_MASK (0x1F801074). Devices raise lines; the
// CPU sees COP0 Cause.IP2 while (I_STAT & I_MASK) != 0. I_STAT bits are acknowledged by writing 0.
#pragma once
#include "core/state.h"
#include "core/types.h"

namespace psx {

// Interrupt lines in I_STAT bit order (psx-spx "Interrupts").
enum class Irq : u32 {
  VBlank = 0,
  Gpu = 1,
  Cdrom = 2,
  Dma = 3,
  Timer0 = 4,
  Timer1 = 5,
  Timer2 = 6,
  PadMemcard = 7,
  Sio = 8,
  Spu = 9,
  Lightpen = 10,
};

class InterruptController {
 public:
  void raise(Irq line) { stat_ |= 1u << static_cast<u32>(line); }
  bool pending() const { return (stat_ & mask_) != 0; }

  u32 read(u32 offset) const;
  void write(u32 offset, u32 value);

  u32 stat() const { return stat_; }
  u32 mask() const { return mask_; }
  // Where I_STAT and I_MASK live: the recompiler's native code (cpu/recompiler/) checks for a
  // pending interrupt in place.
  const u32* stat_cell() const { return &stat_; }
  const u32* mask_cell() const { return &mask_; }

  void do_state(StateIO& s) {
    s.section("IRQC", 1);
    s.pod(stat_);
    s.pod(mask_);
    s.end_section("IRQC");
  }

 private:
  static constexpr u32 kUsedBits = 0x7FF;
  u32 stat_ = 0;
  u32 mask_ = 0;
};

}  // namespace psx
