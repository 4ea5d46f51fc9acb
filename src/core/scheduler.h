// The console's single timeline. Every device books its future work here in CPU cycles; the CPU
// runs until the earliest booking, then the scheduler dispatches the events that are due.
// Nothing here reads a host clock: time is only the emulated cycle counter.
#pragma once
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/state.h"
#include "core/types.h"

namespace psx {

class Scheduler {
 public:
  using Handle = int;
  // `late` is how many cycles after its booked time the event actually ran (0 unless the CPU
  // overshot the deadline inside one instruction or a DMA burst).
  using Callback = std::function<void(Cycles late)>;

  static constexpr Cycles kNever = std::numeric_limits<Cycles>::max();

  // Events are registered once, in a fixed order, when the console is built; the order is what
  // makes two same-time events dispatch deterministically. Save states name each event, so every
  // name must be unique (a second use is a programming error: std::logic_error).
  Handle add_event(std::string name, Callback cb);

  void schedule(Handle h, Cycles delay) { schedule_at(h, now_ + delay); }
  void schedule_at(Handle h, Cycles when);
  void cancel(Handle h);
  bool pending(Handle h) const { return events_[h].when != kNever; }
  Cycles when(Handle h) const { return events_[h].when; }
  // The event registered under `name`, or -1.
  Handle find(const std::string& name) const;

  Cycles now() const { return now_; }
  // Earliest booked time (kNever when nothing is booked).
  Cycles next_deadline() const { return next_; }
  // The CPU (and DMA, which holds the bus) move time forward.
  void advance(Cycles n) { now_ += n; }
  // Where the time and the deadline live: the recompiler's native code (cpu/recompiler/) counts
  // cycles and checks the deadline in place instead of calling advance() and next_deadline().
  Cycles* now_cell() { return &now_; }
  const Cycles* deadline_cell() const { return &next_; }
  // Runs every event whose time has come, earliest first, ties by registration order. A
  // callback may book new events, including ones due now; those run too.
  void run_due_events();
  // For a device that does its work lazily instead of booking an event at every step (the SPU,
  // spu/spu.h): the latest time up to which event `h`, were it booked at every cycle, would
  // already have run. Outside dispatch that is now; inside the callback of the event booked at E,
  // it is E if `h` would run before that event at a tie (lower or equal handle), else E - 1.
  Cycles horizon(Handle h) const {
    if (dispatching_ < 0) return now_;
    return h <= dispatching_ ? dispatch_time_ : dispatch_time_ - 1;
  }

  // Saves the time and each booked event by name. Loading refuses a booked name this build does
  // not have (the state's future would lose that event's work); an event of this build that the
  // state does not name was unbooked when the state was made (or did not exist) and stays so.
  void do_state(StateIO& s);

 private:
  struct Event {
    std::string name;
    Callback cb;
    Cycles when = kNever;
  };
  void recompute_next();
  void read_bookings(StateIO& s, u32 version);

  std::vector<Event> events_;
  Cycles now_ = 0;
  Cycles next_ = kNever;
  // The event whose callback runs (-1 when none) and the time it was booked for.
  Handle dispatching_ = -1;
  Cycles dispatch_time_ = 0;
};

}  // namespace psx
