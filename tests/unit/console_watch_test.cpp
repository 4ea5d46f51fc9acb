// Memory watches (issue 8; the seed's listeners §3.1.3): every guest write in a watched range is
// reported once, in order, with old and new values; fresh-only, sleep and the flow limit.
#include <gtest/gtest.h>

#include "core/console.h"

namespace psx {
namespace {

const std::string kWatchExe = PSXRL_BUILD_DIR "/tests/roms/watch_writes.exe";

struct Expected {
  u32 address, width, old_value, new_value;
};

void expect_events(const std::vector<WatchEvent>& got, const std::vector<Expected>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) {
    SCOPED_TRACE("event " + std::to_string(i));
    EXPECT_EQ(got[i].key, "w");
    EXPECT_EQ(got[i].address, want[i].address);
    EXPECT_EQ(got[i].width, want[i].width);
    EXPECT_EQ(got[i].old_value, want[i].old_value);
    EXPECT_EQ(got[i].new_value, want[i].new_value);
  }
}

// The stores watch_writes.c makes into 0x80100000..0x8010000F (RAM starts zeroed).
const std::vector<Expected> kAllWrites = {
    {0x100000, 1, 0, 0x11},
    {0x100002, 2, 0, 0x2233},
    {0x100004, 4, 0, 0x44556677},
    {0x100004, 4, 0x44556677, 0x44556677},
    {0x100008, 4, 0, 0x8899AABB},
};

TEST(ConsoleWatch, ReportsEveryCpuStoreInOrder) {
  Console c;
  c.boot_exe(kWatchExe);
  c.watch("w", 0x80100000, 16);
  c.run_frames(5);
  ASSERT_EQ(c.exit_code(), 0u);
  expect_events(c.take_watch_events(), kAllWrites);
  EXPECT_TRUE(c.take_watch_events().empty());  // taken events are gone
}

TEST(ConsoleWatch, FreshOnlyDropsUnchangedValues) {
  Console c;
  c.boot_exe(kWatchExe);
  c.watch("w", 0xA0100000, 16, /*fresh_only=*/true);  // any segment names the same RAM
  c.run_frames(5);
  expect_events(c.take_watch_events(), {kAllWrites[0], kAllWrites[1], kAllWrites[2], kAllWrites[4]});
}

TEST(ConsoleWatch, SleepingWatchReportsNothingAndWakes) {
  Console c;
  c.boot_exe(kWatchExe);
  c.watch("w", 0x80100000, 16);
  c.sleep_watch("w");
  c.run_frames(5);
  EXPECT_TRUE(c.take_watch_events().empty());
  c.wake_watch("w");
  c.write32(0x80100000, 0);  // host writes are not guest writes
  EXPECT_TRUE(c.take_watch_events().empty());
}

TEST(ConsoleWatch, RejectsBadRanges) {
  Console c;
  EXPECT_THROW(c.watch("x", 0x80100000, 0), std::invalid_argument);
  EXPECT_THROW(c.watch("x", 0x801FFFFC, 8), std::invalid_argument);  // runs past 2 MiB
  EXPECT_THROW(c.watch("x", 0x1F801070, 4), std::invalid_argument);  // I/O, not memory
  c.watch("x", 0x80000000, 4);
  EXPECT_THROW(c.watch("x", 0x80000010, 4), std::invalid_argument);  // key in use
  EXPECT_THROW(c.unwatch("y"), std::invalid_argument);
}

// Flow limit: at most 2 events per window of N frames; the rest of the window's writes become
// one event (first old value, last new value) delivered when the window ends.
TEST(MemoryWatchFlowLimit, TwoPerWindowThenCoalesced) {
  MemoryWatches w;
  w.watch("w", 0x80000100, 4, false, 3);
  for (u32 v = 1; v <= 5; ++v) w.on_write(0x100, 4, v - 1, v, /*frame=*/10, /*cycle=*/v);
  w.on_frame(11, 100);
  w.on_frame(12, 200);
  auto e = w.take_events();
  ASSERT_EQ(e.size(), 2u);  // window [10, 13) has not ended
  EXPECT_EQ(e[1].new_value, 2u);
  w.on_frame(13, 300);
  e = w.take_events();
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].old_value, 2u);  // first suppressed write's old value
  EXPECT_EQ(e[0].new_value, 5u);  // last write's new value
  EXPECT_EQ(e[0].frame, 13u);
  // The delivered event counts towards the new window [13, 16): one more fits, then coalesce.
  w.on_write(0x100, 4, 5, 6, 14, 400);
  w.on_write(0x100, 4, 6, 7, 14, 401);
  EXPECT_EQ(w.take_events().size(), 1u);
}

TEST(ConsoleMemory, HostAccessNeedsRamOrScratchpad) {
  Console c;
  c.write32(0x80001000, 0x12345678);
  EXPECT_EQ(c.read32(0xA0001000), 0x12345678u);
  EXPECT_EQ(c.read16(0x00001002), 0x1234u);
  EXPECT_EQ(c.read8(0x80601001), 0x56);  // fourth 2 MiB mirror
  EXPECT_EQ(c.ram()[0x1000], 0x78);
  c.write8(0x1F800004, 0xAB);
  EXPECT_EQ(c.scratchpad()[4], 0xAB);
  EXPECT_THROW(c.read32(0x1F801070), std::invalid_argument);
  EXPECT_THROW(c.read32(0x80001002), std::invalid_argument);  // misaligned
}

}  // namespace
}  // namespace psx
