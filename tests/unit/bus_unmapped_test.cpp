// Unmapped accesses are reported once per address, and the set of reported addresses is bounded:
// a program sweeping unmapped space (physical 00800000h-1EFFFFFFh is unused, psx-spx "Memory
// Map") must not grow the host's memory or log per address.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/bus.h"
#include "core/irq.h"
#include "core/scheduler.h"

namespace psx {
namespace {

TEST(BusUnmapped, ReportedAddressesAreCapped) {
  Scheduler sched;
  InterruptController irq;
  Bus bus(sched, irq);
  std::vector<std::string> log;
  bus.on_log = [&log](const std::string& m) { log.push_back(m); };
  const u32 distinct = 10 * Bus::kMaxUnmappedReported;
  u32 v = 0;
  for (u32 i = 0; i < distinct; ++i) {
    EXPECT_FALSE(bus.read32(0x10000000 + 4 * i, v));
    EXPECT_FALSE(bus.read32(0x10000000 + 4 * i, v));  // a second access to it: not reported again
  }
  EXPECT_EQ(bus.unmapped_reported(), Bus::kMaxUnmappedReported);
  ASSERT_EQ(log.size(), Bus::kMaxUnmappedReported + 1);
  EXPECT_EQ(log.front(), "unmapped read at 0x10000000 (reported once)");
  EXPECT_EQ(log.back(), "further unmapped accesses not reported (64 addresses reported)");
}

}  // namespace
}  // namespace psx
