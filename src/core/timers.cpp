// Root counters: lazy counting from the CPU clock, dot clock, system clock / 8 and HBlank edges,
// synchronisation to the blanking periods, and the COMP / 0xFFFF interrupt logic.
#include "core/timers.h"

#include <algorithm>
#include <utility>

#include "core/irq.h"

namespace psx {

namespace {
constexpr u64 kNoIrq = ~u64{0};
// A dot lasts `divider` cycles of the GPU video clock. Timer 0's dot phase is kept in units of
// 1/(kCpuClockHz * divider) dots: each CPU cycle adds video_hz units and a dot costs
// kCpuClockHz * divider (at most 338,688,000, so the phase fits in 32 bits).
constexpr Irq kTimerIrq[3] = {Irq::Timer0, Irq::Timer1, Irq::Timer2};
}  // namespace

Timers::Timers(Scheduler& sched, InterruptController& irq) : sched_(sched), irq_(irq) {
  event_ = sched_.add_event("timers", [this](Cycles) {
    catch_up();
    reschedule();
  });
}

bool Timers::counts_time(u32 i) const { return !(i == 1 && (counters_[1].mode & kExtc)); }

bool Timers::irq_armed(const Counter& c) const {
  if (!(c.mode & (kCmp | kOvfl))) return false;
  return (c.mode & kRept) || !c.irq_done;
}

bool Timers::gate_open(u32 i) const {
  const Counter& c = counters_[i];
  if (!(c.mode & kGatf)) return true;
  u32 sync = (c.mode >> 1) & 3;
  if (i == 2) return sync == 1 || sync == 2;  // 0 and 3 stop timer 2; 1 and 2 run freely
  bool blank = i == 0 ? hblank_ : vblank_;
  switch (sync) {
    case 0: return !blank;   // pause during blank
    case 1: return true;     // reset at blank start
    case 2: return blank;    // reset at blank start, pause outside blank
    default: return c.released;  // pause until the first blank, then run freely
  }
}

u64 Timers::source_ticks(u32 i, Cycles elapsed) {
  Counter& c = counters_[i];
  // The dot clock and the /8 prescaler run freely whatever the counter selects.
  if (i == 0) {
    u64 unit = u64{kCpuClockHz} * dot_divider_;
    u64 total = c.phase + video_hz_ * elapsed;
    c.phase = static_cast<u32>(total % unit);
    return (c.mode & kExtc) ? total / unit : elapsed;
  }
  if (i == 2) {
    u64 total = c.phase + elapsed;
    c.phase = static_cast<u32>(total % 8);
    return (c.mode & kPscl) ? total / 8 : elapsed;
  }
  if (!(c.mode & kExtc)) return elapsed;
  if (!video_) return 0;  // no video timing, no HBlanks
  // Timer 1 on HBlanks: the starts since the last catch-up (synced_at_ is now).
  const u64 hblanks = video_->hblanks_by(synced_at_);
  return hblanks - std::exchange(hblank_mark_, hblanks);
}

Cycles Timers::cycles_for_ticks(u32 i, u64 ticks) const {
  const Counter& c = counters_[i];
  if (i == 0 && (c.mode & kExtc)) {
    u64 need = ticks * kCpuClockHz * dot_divider_ - c.phase;
    return (need + video_hz_ - 1) / video_hz_;
  }
  if (i == 2 && (c.mode & kPscl)) return ticks * 8 - c.phase;
  return ticks;
}

u64 Timers::segment(const Counter& c, u32& reach) {
  reach = 0;
  if (c.hold) return 1;
  if (((c.mode & kZret) && c.value == c.target) || c.value == 0xFFFF) {
    if (c.target == 0) reach = kReachTarget;  // the reset to 0 lands on COMP = 0
    return 1;
  }
  u16 stop = c.value < c.target ? c.target : 0xFFFF;
  if (stop == c.target) reach |= kReachTarget;
  if (stop == 0xFFFF) reach |= kReachMax;
  return stop - c.value;
}

void Timers::take_segment(Counter& c) {
  if (c.hold) {
    c.hold = false;
  } else if ((c.mode & kZret) && c.value == c.target) {
    c.value = 0;
    c.hold = true;  // a reset at COMP stays at 0 for two ticks, a wrap at 0xFFFF for one
  } else if (c.value == 0xFFFF) {
    c.value = 0;
  } else {
    c.value = c.value < c.target ? c.target : 0xFFFF;
  }
}

void Timers::advance(u32 i, u64 ticks) {
  Counter& c = counters_[i];
  while (ticks > 0) {
    bool zret = c.mode & kZret;
    bool in_cycle = zret ? c.value <= c.target && (!c.hold || c.value == 0) : !c.hold;
    u64 period = zret ? u64{c.target} + 2 : 0x10000;
    if (!irq_armed(c) && in_cycle && ticks >= 2 * period) {
      // Whole periods with no interrupt to raise only set the reached flags.
      c.mode |= kEquf;
      if (!zret || c.target == 0xFFFF) c.mode |= kOvff;
      ticks %= period;
      continue;
    }
    u32 reach;
    u64 len = segment(c, reach);
    if (ticks < len) {
      c.value = static_cast<u16>(c.value + ticks);
      return;
    }
    take_segment(c);
    ticks -= len;
    if (reach) reached(i, reach);
  }
}

void Timers::reached(u32 i, u32 reach) {
  Counter& c = counters_[i];
  if (reach & kReachTarget) c.mode |= kEquf;
  if (reach & kReachMax) c.mode |= kOvff;
  bool wanted = ((reach & kReachTarget) && (c.mode & kCmp)) || ((reach & kReachMax) && (c.mode & kOvfl));
  if (!wanted || !irq_armed(c)) return;
  c.irq_done = true;
  if (c.mode & kLevl) {
    // Toggle mode: INTF flips on each event; the IRQ line sees only its 1-to-0 edges.
    c.mode ^= kIntf;
    if (!(c.mode & kIntf)) irq_.raise(kTimerIrq[i]);
  } else {
    // Pulse mode: INTF drops for a few cycles only, so it reads back as 1.
    irq_.raise(kTimerIrq[i]);
  }
}

u64 Timers::ticks_to_irq(const Counter& c) const {
  if (!irq_armed(c)) return kNoIrq;
  Counter d = c;
  u64 total = 0;
  // At most: a held tick, the run to 0xFFFF, the wrap, the run to COMP.
  for (int k = 0; k < 6; ++k) {
    u32 reach;
    total += segment(d, reach);
    take_segment(d);
    if (((reach & kReachTarget) && (d.mode & kCmp)) || ((reach & kReachMax) && (d.mode & kOvfl))) return total;
  }
  return kNoIrq;  // e.g. only the 0xFFFF IRQ enabled while the counter resets at a lower COMP
}

void Timers::catch_up() {
  Cycles now = sched_.now();
  if (now == synced_at_) return;
  Cycles elapsed = now - synced_at_;
  synced_at_ = now;
  for (u32 i = 0; i < 3; ++i) {
    u64 ticks = source_ticks(i, elapsed);
    if (ticks && gate_open(i)) advance(i, ticks);
  }
}

void Timers::reschedule() {
  Cycles best = Scheduler::kNever;
  for (u32 i = 0; i < 3; ++i) {
    if (!gate_open(i)) continue;
    u64 ticks = ticks_to_irq(counters_[i]);
    if (ticks == kNoIrq) continue;
    if (counts_time(i)) best = std::min(best, cycles_for_ticks(i, ticks));
    else if (video_) best = std::min(best, video_->hblank_time(hblank_mark_ + ticks) - sched_.now());
  }
  if (best == Scheduler::kNever) sched_.cancel(event_);
  else sched_.schedule(event_, best);
}

void Timers::blank_start(u32 i) {
  Counter& c = counters_[i];
  if (!(c.mode & kGatf)) return;
  u32 sync = (c.mode >> 1) & 3;
  if (sync == 1 || sync == 2) {
    c.value = 0;
    c.hold = false;
  }
  if (sync == 3) c.released = true;
}

bool Timers::wants_hblank() const { return counters_[0].mode & kGatf; }

void Timers::hblank_changed(bool active) {
  catch_up();
  hblank_ = active;
  if (active) blank_start(0);
  reschedule();
}

void Timers::vblank_changed(bool active) {
  catch_up();
  vblank_ = active;
  if (active) blank_start(1);
  reschedule();
}

void Timers::dot_clock_changed(u64 video_hz, u32 video_cycles_per_dot) {
  if (video_hz == 0 || video_cycles_per_dot == 0) return;
  if (video_hz == video_hz_ && video_cycles_per_dot == dot_divider_) return;
  catch_up();
  // Keep the fraction of the current dot that has elapsed (the phase unit scales with the divider).
  Counter& c = counters_[0];
  c.phase = static_cast<u32>(u64{c.phase} * video_cycles_per_dot / dot_divider_);
  video_hz_ = video_hz;
  dot_divider_ = video_cycles_per_dot;
  reschedule();
}

u32 Timers::io_read(u32 offset, u32 width) {
  u32 i = offset >> 4;
  if (i >= 3) return 0;
  catch_up();
  Counter& c = counters_[i];
  u32 v = 0;
  switch (offset & 0xC) {
    case 0x0: v = c.value; break;
    case 0x4:
      v = c.mode;
      c.mode &= ~(kEquf | kOvff);  // reached flags reset after reading
      break;
    case 0x8: v = c.target; break;
    default: break;
  }
  return v >> ((offset & 3) * 8);
}

void Timers::io_write(u32 offset, u32 value, u32 width) {
  u32 i = offset >> 4;
  if (i >= 3) return;
  catch_up();
  Counter& c = counters_[i];
  u16 v = static_cast<u16>(value << ((offset & 3) * 8));
  switch (offset & 0xC) {
    case 0x0:
      c.value = v;
      c.hold = true;
      break;
    case 0x4: {
      // Writing MODE resets the counter, sets INTF and re-arms a one-shot IRQ. HBlank edges reach
      // the timers only while they want them (VideoSignals), so the state is read before a
      // change, while the edges up to now still count as unwanted.
      const bool wanted = wants_hblank();
      if (video_ && !wanted) hblank_ = video_->hblank_now();
      c.mode = static_cast<u16>((v & 0x3FF) | kIntf | (c.mode & (kEquf | kOvff)));
      // The very next source tick counts: with timer 1 on HBlanks and timer 0 on dots, reset
      // together, a console reads 341 dots a line in 256-pixel NTSC mode (pcsx-redux
      // src/mips/tests/timers, run on hardware), where a held first tick would give 348.
      c.value = 0;
      c.hold = false;
      c.irq_done = false;
      c.released = false;
      // Timer 1 counts the HBlanks from here (catch_up() counted up to now for the old mode).
      if (i == 1 && (c.mode & kExtc) && video_) hblank_mark_ = video_->hblanks_by(sched_.now());
      if (video_ && wants_hblank() != wanted) video_->hblank_wanted_changed();
      break;
    }
    case 0x8: c.target = v; break;
    default: break;
  }
  reschedule();
}

void Timers::do_state(StateIO& s) {
  // Version 3 adds the HBlank count timer 1 has reached (version 2 loads it as 0, as the video
  // timing's version 1 loads its count).
  const u32 version = s.section("TMRS", 3, 2);
  for (Counter& c : counters_) {
    s.pod(c.value);
    s.pod(c.mode);
    s.pod(c.target);
    s.boolean(c.hold);
    s.boolean(c.irq_done);
    s.boolean(c.released);
    s.pod(c.phase);
  }
  s.pod(synced_at_);
  s.boolean(hblank_);
  s.boolean(vblank_);
  s.pod(video_hz_);
  s.pod(dot_divider_);
  if (version >= 3) s.pod(hblank_mark_);
  else hblank_mark_ = 0;
  s.end_section("TMRS");
}

}  // namespace psx
