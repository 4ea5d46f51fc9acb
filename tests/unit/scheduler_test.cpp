// The scheduler's dispatch rules (src/core/scheduler.h): due events run earliest first, events
// booked for the same cycle run in registration order, a callback's bookings that are already
// due run in the same pass, `late` is how far time had passed the booking, and the deadline is
// always the earliest booking left.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/scheduler.h"

namespace psx {
namespace {

struct Recorder {
  Scheduler sched;
  std::vector<std::string> ran;
  std::vector<Cycles> lates;
  Scheduler::Handle add(const std::string& name) {
    return sched.add_event(name, [this, name](Cycles late) {
      ran.push_back(name);
      lates.push_back(late);
    });
  }
};

TEST(Scheduler, DueEventsRunEarliestFirst) {
  Recorder r;
  const auto a = r.add("a"), b = r.add("b"), c = r.add("c");
  r.sched.schedule_at(a, 30);
  r.sched.schedule_at(b, 10);
  r.sched.schedule_at(c, 20);
  EXPECT_EQ(r.sched.next_deadline(), 10u);
  r.sched.advance(25);
  r.sched.run_due_events();
  EXPECT_EQ(r.ran, (std::vector<std::string>{"b", "c"}));
  EXPECT_EQ(r.lates, (std::vector<Cycles>{15, 5}));  // now 25 against bookings at 10 and 20
  EXPECT_EQ(r.sched.next_deadline(), 30u);  // a, not yet due, is the deadline left
  EXPECT_TRUE(r.sched.pending(a));
  EXPECT_FALSE(r.sched.pending(b));
}

TEST(Scheduler, SameCycleEventsRunInRegistrationOrder) {
  Recorder r;
  const auto first = r.add("first"), second = r.add("second"), third = r.add("third");
  // Booked in the reverse order: registration, not booking, decides.
  r.sched.schedule_at(third, 40);
  r.sched.schedule_at(second, 40);
  r.sched.schedule_at(first, 40);
  r.sched.advance(40);
  r.sched.run_due_events();
  EXPECT_EQ(r.ran, (std::vector<std::string>{"first", "second", "third"}));
  EXPECT_EQ(r.sched.next_deadline(), Scheduler::kNever);
}

TEST(Scheduler, BookingsMadeByACallbackRunInTheSamePassWhenDue) {
  Scheduler sched;
  std::vector<std::string> ran;
  Scheduler::Handle later = -1, chained = -1;
  const auto starter = sched.add_event("starter", [&](Cycles) {
    ran.push_back("starter");
    sched.schedule_at(chained, sched.now());  // due at once
    sched.schedule(later, 100);               // not due in this pass
  });
  chained = sched.add_event("chained", [&](Cycles) { ran.push_back("chained"); });
  later = sched.add_event("later", [&](Cycles) { ran.push_back("later"); });
  sched.schedule_at(starter, 5);
  sched.advance(5);
  sched.run_due_events();
  EXPECT_EQ(ran, (std::vector<std::string>{"starter", "chained"}));
  EXPECT_EQ(sched.next_deadline(), 105u);
}

TEST(Scheduler, NothingDueLeavesEveryBooking) {
  Recorder r;
  const auto a = r.add("a");
  r.sched.schedule_at(a, 50);
  r.sched.advance(49);
  r.sched.run_due_events();
  EXPECT_TRUE(r.ran.empty());
  EXPECT_EQ(r.sched.next_deadline(), 50u);
  r.sched.cancel(a);
  EXPECT_EQ(r.sched.next_deadline(), Scheduler::kNever);
}

}  // namespace
}  // namespace psx
