// Save-state format rules (src/core/state.h, docs/save-states.md): sections carry version and
// length, an older section version loads through the block's migration, a newer one is refused
// by name, and scheduler events are matched by name, not registration order.
#include <gtest/gtest.h>

#include "core/scheduler.h"
#include "core/state.h"

namespace psx {
namespace {

// A test-only block whose version 1 had two fields; version 2 added `gain`, which was 256 (unity)
// before it could be set.
struct BlockV1 {
  u32 counter = 0;
  u16 mode = 0;
  void do_state(StateIO& s) {
    s.section("TBLK", 1);
    s.pod(counter);
    s.pod(mode);
    s.end_section("TBLK");
  }
};

struct BlockV2 {
  u32 counter = 0;
  u16 mode = 0;
  u32 gain = 7;
  void do_state(StateIO& s) {
    const u32 v = s.section("TBLK", 2, 1);
    s.pod(counter);
    s.pod(mode);
    s.pod_since(v, 2, gain, u32{256});
    s.end_section("TBLK");
  }
};

std::string error_of(const std::vector<u8>& blob, BlockV1& b) {
  try {
    StateIO r(blob.data(), blob.size());
    b.do_state(r);
    r.finish();
  } catch (const StateError& e) {
    return e.what();
  }
  return "";
}

TEST(StateFormat, SectionHeaderIsTagVersionLength) {
  BlockV1 b{0x11223344, 0x5566};
  StateIO w;
  b.do_state(w);
  w.finish();
  // 4 tag bytes, u32 version 1, u32 body length 6 (u32 + u16), then the body, little-endian.
  const std::vector<u8> expect = {'T', 'B', 'L', 'K', 1, 0, 0, 0, 6, 0, 0, 0, 0x44, 0x33, 0x22, 0x11, 0x66, 0x55};
  EXPECT_EQ(w.buffer(), expect);
}

TEST(StateFormat, OlderVersionLoadsThroughTheMigrationWithDefaults) {
  BlockV1 old{1234, 3};
  StateIO w;
  old.do_state(w);
  BlockV2 now;
  StateIO r(w.buffer().data(), w.buffer().size());
  now.do_state(r);
  r.finish();
  EXPECT_EQ(now.counter, 1234u);
  EXPECT_EQ(now.mode, 3u);
  EXPECT_EQ(now.gain, 256u);  // the migration's default, not the object's previous 7

  // The current version round-trips the new field.
  BlockV2 a{9, 8, 77}, b;
  StateIO w2;
  a.do_state(w2);
  StateIO r2(w2.buffer().data(), w2.buffer().size());
  b.do_state(r2);
  r2.finish();
  EXPECT_EQ(b.gain, 77u);
}

TEST(StateFormat, NewerVersionIsRefusedNamingTheSection) {
  BlockV2 newer{1, 2, 3};
  StateIO w;
  newer.do_state(w);
  BlockV1 reader;
  const std::string e = error_of(w.buffer(), reader);
  EXPECT_NE(e.find("section 'TBLK' has version 2, newer than this build reads (1)"), std::string::npos) << e;
}

TEST(StateFormat, VersionBelowTheOldestReadIsRefused) {
  StateIO w;
  w.section("TBLK", 1);
  w.end_section("TBLK");
  StateIO r(w.buffer().data(), w.buffer().size());
  try {
    r.section("TBLK", 3, 2);
    FAIL() << "version 1 was accepted";
  } catch (const StateError& e) {
    EXPECT_NE(std::string(e.what()).find("version 1, older than this build reads (2 to 3)"), std::string::npos)
        << e.what();
  }
}

TEST(StateFormat, LengthCatchesALayoutChangeWithoutAVersionBump) {
  // A section claiming version 1 but with an extra field: the reader stops at its block.
  BlockV2 grown{1, 2, 3};
  StateIO w;
  w.section("TBLK", 1);
  w.pod(grown.counter);
  w.pod(grown.mode);
  w.pod(grown.gain);
  w.end_section("TBLK");
  BlockV1 reader;
  std::string e = error_of(w.buffer(), reader);
  EXPECT_NE(e.find("section 'TBLK' version 1 has 4 bytes this build did not read"), std::string::npos) << e;

  // One field short: the read stops at the section's end, not in the next block's bytes.
  StateIO w2;
  w2.section("TBLK", 1);
  w2.pod(grown.counter);
  w2.end_section("TBLK");
  w2.section("NEXT", 1);
  w2.pod(grown.gain);
  w2.end_section("NEXT");
  e = error_of(w2.buffer(), reader);
  EXPECT_NE(e.find("section 'TBLK' version 1 ends early"), std::string::npos) << e;
}

TEST(StateFormat, Format1SectionsHaveNoLength) {
  // Container format 1 wrote tag and version only.
  const std::vector<u8> v1 = {'T', 'B', 'L', 'K', 1, 0, 0, 0, 0x44, 0x33, 0x22, 0x11, 0x66, 0x55};
  BlockV2 b;
  StateIO r(v1.data(), v1.size(), StateIO::kUnsizedSections);
  b.do_state(r);
  r.finish();
  EXPECT_EQ(b.counter, 0x11223344u);
  EXPECT_EQ(b.mode, 0x5566u);
  EXPECT_EQ(b.gain, 256u);
}

TEST(StateFormat, UnclosedSectionIsAProgrammingError) {
  StateIO w;
  w.section("TBLK", 1);
  EXPECT_THROW(w.finish(), std::logic_error);
  EXPECT_THROW(w.end_section("OTHR"), std::logic_error);
}

// Scheduler events are saved by name: another registration order, or an event added since,
// does not disturb a state's bookings.
TEST(SchedulerState, EventsAreMatchedByName) {
  Scheduler a;
  auto noop = [](Cycles) {};
  Scheduler::Handle a_video = a.add_event("gpu.video", noop), a_dma = a.add_event("dma", noop);
  a.add_event("timers", noop);  // unbooked: not saved
  a.advance(100);
  a.schedule(a_video, 50);
  a.schedule(a_dma, 7);
  StateIO w;
  a.do_state(w);

  Scheduler b;
  Scheduler::Handle b_new = b.add_event("spu.sample", noop), b_dma = b.add_event("dma", noop);
  Scheduler::Handle b_timers = b.add_event("timers", noop), b_video = b.add_event("gpu.video", noop);
  b.schedule_at(b_new, 5);
  b.schedule_at(b_timers, 9);
  StateIO r(w.buffer().data(), w.buffer().size());
  b.do_state(r);
  r.finish();
  EXPECT_EQ(b.now(), 100u);
  EXPECT_EQ(b.when(b_video), 150u);
  EXPECT_EQ(b.when(b_dma), 107u);
  EXPECT_FALSE(b.pending(b_new));     // this build's event the state does not have
  EXPECT_FALSE(b.pending(b_timers));  // unbooked when saved
  EXPECT_EQ(b.next_deadline(), 107u);
}

TEST(SchedulerState, UnknownBookedEventIsRefusedByName) {
  Scheduler a;
  auto noop = [](Cycles) {};
  a.schedule(a.add_event("cdrom.motor", noop), 10);
  StateIO w;
  a.do_state(w);
  Scheduler b;
  b.add_event("dma", noop);
  StateIO r(w.buffer().data(), w.buffer().size());
  try {
    b.do_state(r);
    FAIL() << "an unknown event was accepted";
  } catch (const StateError& e) {
    EXPECT_NE(std::string(e.what()).find("'cdrom.motor' is booked in the state but this build has no such event"),
              std::string::npos)
        << e.what();
  }
}

// Version 1 (container format 1) saved the time of all 11 console events in registration order,
// unbooked ones as "never"; the migration maps them to names (scheduler.cpp kVersion1Events).
TEST(SchedulerState, Version1SectionIsReadByTheFrozenOrder) {
  StateIO w;
  w.section("SCHD", 1);
  u64 now = 1000;
  w.pod(now);
  u32 n = 11;
  w.pod(n);
  for (u32 i = 0; i < n; ++i) {
    u64 when = i == 6 ? 1500 : i == 7 ? 1768 : Scheduler::kNever;  // gpu.video, spu.sample
    w.pod(when);
  }
  w.end_section("SCHD");
  const std::vector<u8> v1(w.buffer().begin(), w.buffer().end());
  // Format 1 had no length field: drop the 4 bytes after tag and version.
  std::vector<u8> unsized(v1.begin(), v1.begin() + 8);
  unsized.insert(unsized.end(), v1.begin() + 12, v1.end());

  Scheduler s;
  auto noop = [](Cycles) {};
  Scheduler::Handle sample = s.add_event("spu.sample", noop), video = s.add_event("gpu.video", noop);
  Scheduler::Handle dma = s.add_event("dma", noop);
  StateIO r(unsized.data(), unsized.size(), StateIO::kUnsizedSections);
  s.do_state(r);
  r.finish();
  EXPECT_EQ(s.now(), 1000u);
  EXPECT_EQ(s.when(video), 1500u);
  EXPECT_EQ(s.when(sample), 1768u);
  EXPECT_FALSE(s.pending(dma));
}

TEST(SchedulerState, DuplicateEventNamesAreAProgrammingError) {
  Scheduler s;
  s.add_event("dma", [](Cycles) {});
  EXPECT_THROW(s.add_event("dma", [](Cycles) {}), std::logic_error);
}

}  // namespace
}  // namespace psx
