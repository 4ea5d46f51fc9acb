// Scheduler: event booking and ordered dispatch on the CPU-cycle timeline.
#include "core/scheduler.h"

namespace psx {

Scheduler::Handle Scheduler::add_event(std::string name, Callback cb) {
  events_.push_back(Event{std::move(name), std::move(cb), kNever});
  return static_cast<Handle>(events_.size() - 1);
}

void Scheduler::schedule_at(Handle h, Cycles when) {
  events_[h].when = when;
  if (when < next_) next_ = when;
}

void Scheduler::cancel(Handle h) {
  if (events_[h].when == kNever) return;
  events_[h].when = kNever;
  recompute_next();
}

void Scheduler::recompute_next() {
  next_ = kNever;
  for (const Event& e : events_)
    if (e.when < next_) next_ = e.when;
}

void Scheduler::run_due_events() {
  for (;;) {
    recompute_next();
    if (next_ > now_) return;
    // Earliest due event; ties go to the lowest handle.
    Handle due = -1;
    for (Handle h = 0; h < static_cast<Handle>(events_.size()); ++h)
      if (events_[h].when <= now_ && (due < 0 || events_[h].when < events_[due].when)) due = h;
    Cycles late = now_ - events_[due].when;
    events_[due].when = kNever;
    events_[due].cb(late);
  }
}

void Scheduler::do_state(StateIO& s) {
  s.section("SCHD", 1);
  s.pod(now_);
  u32 n = static_cast<u32>(events_.size());
  s.pod(n);
  if (s.loading() && n != events_.size())
    s.fail("scheduler has " + std::to_string(n) + " events, this console has " + std::to_string(events_.size()));
  for (Event& e : events_) s.pod(e.when);
  if (s.loading()) recompute_next();
}

}  // namespace psx
