// Scheduler: event booking and ordered dispatch on the CPU-cycle timeline.
#include "core/scheduler.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace psx {

Scheduler::Handle Scheduler::add_event(std::string name, Callback cb) {
  if (find(name) >= 0) throw std::logic_error("scheduler event '" + name + "' registered twice");
  events_.push_back(Event{std::move(name), std::move(cb), kNever});
  return static_cast<Handle>(events_.size() - 1);
}

Scheduler::Handle Scheduler::find(const std::string& name) const {
  for (Handle h = 0; h < static_cast<Handle>(events_.size()); ++h)
    if (events_[h].name == name) return h;
  return -1;
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
  // Outside a callback (also after one that throws) devices see the present (horizon()).
  struct EndDispatch {
    Handle& h;
    ~EndDispatch() { h = -1; }
  } end_dispatch{dispatching_};
  for (;;) {
    // The earliest event (ties go to the lowest handle) is next_, and the one to run when due.
    Handle due = -1;
    next_ = kNever;
    for (Handle h = 0; h < static_cast<Handle>(events_.size()); ++h)
      if (events_[h].when < next_) next_ = events_[h].when, due = h;
    if (next_ > now_) return;
    Cycles late = now_ - events_[due].when;
    dispatching_ = due;
    dispatch_time_ = events_[due].when;
    events_[due].when = kNever;
    events_[due].cb(late);
  }
}

namespace {
// The console's events in registration order while section SCHD had version 1 (container format
// 1, psxrl 0.1), which saved only each event's time, by that order: the names a version-1 section
// means, whatever this build registers.
constexpr const char* kVersion1Events[] = {"cdrom.command", "cdrom.second", "cdrom.drive",   "cdrom.deliver",
                                           "sio0.transfer", "sio0.ack",     "gpu.video",     "spu.sample",
                                           "dma",           "timers",       "run-limit"};
}  // namespace

void Scheduler::do_state(StateIO& s) {
  const u32 version = s.section("SCHD", 2, 1);
  s.pod(now_);
  if (s.loading()) {
    read_bookings(s, version);
  } else {
    auto booked = [](const Event& e) { return e.when != kNever; };
    u32 n = static_cast<u32>(std::count_if(events_.begin(), events_.end(), booked));
    s.pod(n);
    for (Event& e : events_) {
      if (e.when == kNever) continue;
      s.string(e.name);
      s.pod(e.when);
    }
  }
  s.end_section("SCHD");
}

void Scheduler::read_bookings(StateIO& s, u32 version) {
  u32 n = 0;
  s.pod(n);
  const size_t known = version == 1 ? std::size(kVersion1Events) : 256;
  if (n > known) s.fail("scheduler section lists " + std::to_string(n) + " events, at most " + std::to_string(known));
  std::vector<Cycles> when(events_.size(), kNever);
  std::vector<bool> seen(events_.size(), false);
  for (u32 i = 0; i < n; ++i) {
    std::string name = version == 1 ? kVersion1Events[i] : std::string();
    if (version >= 2) s.string(name);
    Cycles t = 0;
    s.pod(t);
    if (t == kNever) continue;  // version 1 listed unbooked events too
    const Handle h = find(name);
    if (h < 0) s.fail("scheduler event '" + name + "' is booked in the state but this build has no such event");
    if (seen[h]) s.fail("scheduler event '" + name + "' appears twice");
    seen[h] = true;
    when[h] = t;
  }
  for (size_t h = 0; h < events_.size(); ++h) events_[h].when = when[h];
  recompute_next();
}

}  // namespace psx
