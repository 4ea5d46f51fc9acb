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
  // makes two same-time events dispatch deterministically and what save states index by.
  Handle add_event(std::string name, Callback cb);

  void schedule(Handle h, Cycles delay) { schedule_at(h, now_ + delay); }
  void schedule_at(Handle h, Cycles when);
  void cancel(Handle h);
  bool pending(Handle h) const { return events_[h].when != kNever; }
  Cycles when(Handle h) const { return events_[h].when; }

  Cycles now() const { return now_; }
  // Earliest booked time (kNever when nothing is booked).
  Cycles next_deadline() const { return next_; }
  // The CPU (and DMA, which holds the bus) move time forward.
  void advance(Cycles n) { now_ += n; }
  // Runs every event whose time has come, earliest first, ties by registration order. A
  // callback may book new events, including ones due now; those run too.
  void run_due_events();

  void do_state(StateIO& s);

 private:
  struct Event {
    std::string name;
    Callback cb;
    Cycles when = kNever;
  };
  void recompute_next();

  std::vector<Event> events_;
  Cycles now_ = 0;
  Cycles next_ = kNever;
};

}  // namespace psx
