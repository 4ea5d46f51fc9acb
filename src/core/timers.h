// Root counters (psx-spx "Timers"): three 16-bit counters at 0x1F801100 + N*0x10 (COUNT, MODE,
// COMP). Timer 0 counts the system clock or the GPU dotclock, timer 1 the system clock or HBlanks,
// timer 2 the system clock or system clock / 8. Timers 0 and 1 can synchronise to HBlank and
// VBlank. Counters are computed lazily from the scheduler's clock, so a read mid-count is exact
// to the cycle; an event is booked only for the next moment a counter can raise an interrupt.
#pragma once
#include <array>

#include "core/io_device.h"
#include "core/scheduler.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

class InterruptController;

class Timers : public IoDevice, public VideoSignals {
 public:
  static constexpr u32 kBase = 0x1F801100;
  static constexpr u32 kSize = 0x30;

  // MODE register bits (psx-spx names).
  static constexpr u16 kGatf = 1u << 0;  // synchronisation enable
  static constexpr u16 kZret = 1u << 3;  // reset after COUNT == COMP (else after 0xFFFF)
  static constexpr u16 kCmp = 1u << 4;   // IRQ at COMP
  static constexpr u16 kOvfl = 1u << 5;  // IRQ at 0xFFFF
  static constexpr u16 kRept = 1u << 6;  // repeat (else one-shot)
  static constexpr u16 kLevl = 1u << 7;  // toggle (else pulse)
  static constexpr u16 kExtc = 1u << 8;  // timers 0/1: dotclock / HBlank source
  static constexpr u16 kPscl = 1u << 9;  // timer 2: divide by 8
  static constexpr u16 kIntf = 1u << 10;  // 0 = interrupt requested
  static constexpr u16 kEquf = 1u << 11;  // reached COMP (cleared by reading MODE)
  static constexpr u16 kOvff = 1u << 12;  // reached 0xFFFF (cleared by reading MODE)

  Timers(Scheduler& sched, InterruptController& irq);

  u32 io_read(u32 offset, u32 width) override;
  void io_write(u32 offset, u32 value, u32 width) override;

  // The GPU's video timing, which the timers ask for the HBlank state when they start wanting its
  // edges (timer 0 synchronised to HBlank) and for the HBlanks timer 1 counts, and when.
  void set_video_clock(VideoClock* clock) { video_ = clock; }
  bool wants_hblank() const override;
  void hblank_changed(bool active) override;
  void vblank_changed(bool active) override;
  void dot_clock_changed(u64 video_hz, u32 video_cycles_per_dot) override;

  void do_state(StateIO& s);

 private:
  struct Counter {
    u16 value = 0;
    u16 mode = kIntf;
    u16 target = 0;
    // The counter holds its value for one extra tick after a COUNT write and after a reset at
    // COMP (psx-spx "Reset and Wrap"); not after a MODE write, on hardware (timers.cpp).
    bool hold = false;
    bool irq_done = false;  // one-shot mode: the IRQ has fired since the last MODE write
    bool released = false;  // sync mode 3: the blank has occurred, counting freely now
    u32 phase = 0;          // divided clocks: fraction of the next tick (see source_ticks)
  };
  enum Reach : u32 { kReachTarget = 1, kReachMax = 2 };

  // Brings every counter up to sched.now().
  void catch_up();
  void reschedule();
  u64 source_ticks(u32 i, Cycles elapsed);
  Cycles cycles_for_ticks(u32 i, u64 ticks) const;
  bool gate_open(u32 i) const;
  bool counts_time(u32 i) const;  // false for timer 1 counting HBlanks
  bool irq_armed(const Counter& c) const;
  void advance(u32 i, u64 ticks);
  // Length in ticks of the counter's next segment (up to COMP, 0xFFFF, a reset or a held tick),
  // and what it reaches at its end.
  static u64 segment(const Counter& c, u32& reach);
  static void take_segment(Counter& c);
  u64 ticks_to_irq(const Counter& c) const;
  void reached(u32 i, u32 reach);
  void blank_start(u32 i);

  Scheduler& sched_;
  InterruptController& irq_;
  VideoClock* video_ = nullptr;
  Scheduler::Handle event_;
  std::array<Counter, 3> counters_{};
  Cycles synced_at_ = 0;
  bool hblank_ = false;  // follows the edges only while wants_hblank()
  // HBlank starts up to synced_at_ (VideoClock::hblanks_by), while timer 1 counts them: they come
  // in closed form, not as edges, so that the CPU is not stopped twice a scanline (Sony's libetc
  // and PSn00bSDK keep timer 1 on HBlanks for VSync()).
  u64 hblank_mark_ = 0;
  bool vblank_ = false;
  // The dot clock: NTSC video clock, 256-pixel mode (10 video cycles per dot) after reset.
  u64 video_hz_ = 53693175;
  u32 dot_divider_ = 10;
};

}  // namespace psx
