// The scratchpad in data-cache mode, seen from the bus (psx-spx "Memory Control", FFFE0130h
// "D-cache" mode): the rules tests/roms/cpu_dcache cannot check from inside the console, because
// they stop it or need a save state.
#include <gtest/gtest.h>

#include <string>

#include "core/bus.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "core/state.h"

namespace psx {
namespace {

constexpr u32 kBcc = 0xFFFE0130;
constexpr u32 kDcacheMode = 0x00000080;  // DS set, RAM clear
constexpr u32 kBiosBcc = 0x0001E988;     // the BIOS's setting: RAM and DS set, scratchpad mode

struct Rig {
  Scheduler sched;
  InterruptController irq;
  Bus bus{sched, irq};
  std::string fatal;
  Rig() {
    bus.on_fatal = [this](const std::string& m) { fatal = m; };
  }
};

TEST(BusDcache, ScratchpadAddressesHangTheBus) {
  Rig r;
  ASSERT_TRUE(r.bus.write32(kBcc, kDcacheMode));
  u32 v;
  r.bus.read32(0x1F800000, v);
  EXPECT_NE(r.fatal.find("scratchpad access at 0x1F800000"), std::string::npos) << r.fatal;
  r.fatal.clear();
  r.bus.write32(0x9F800010, 1);
  EXPECT_FALSE(r.fatal.empty()) << "a store hangs the bus as well";
}

TEST(BusDcache, ScratchpadModeIsUnaffected) {
  Rig r;
  ASSERT_TRUE(r.bus.write32(kBcc, kBiosBcc));
  ASSERT_TRUE(r.bus.write32(0x1F800000, 0x12345678));
  u32 v = 0;
  ASSERT_TRUE(r.bus.read32(0x80000100, v));
  ASSERT_TRUE(r.bus.read32(0x1F800000, v));
  EXPECT_EQ(v, 0x12345678u) << "with RAM set, loads do not fill the scratchpad";
  EXPECT_TRUE(r.fatal.empty());
}

TEST(BusDcache, ModeSurvivesASaveState) {
  Rig a;
  a.bus.write32(kBcc, kDcacheMode);
  StateIO w;
  a.bus.do_state(w);
  Rig b;
  StateIO rd(w.buffer().data(), w.buffer().size());
  b.bus.do_state(rd);
  b.bus.write32(0x80000000, 0xABCD0123);
  u32 v;
  b.bus.read32(0x80000000, v);  // fills slot 0
  b.bus.write32(kBcc, kBiosBcc);
  b.bus.read32(0x1F800000, v);
  EXPECT_EQ(v, 0xABCD0123u);
}

}  // namespace
}  // namespace psx
