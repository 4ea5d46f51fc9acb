// The instruction cache as the bus charges it (psx-spx "Memory Map", i-Cache; "Memory Control",
// FFFE0130h): what tests/roms/cpu_icache cannot reach from a program loaded into RAM. Costs: a
// fill reads each word it fills at the uncached fetch cost, 4 cycles from RAM, and from the BIOS
// ROM the 32-bit read time of its Delay/Size setting (7 + 3 * 6 = 25 cycles, the instruction's
// own cycle not counted: 24; see memory_control_test).
#include <gtest/gtest.h>

#include "core/bus.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "core/state.h"

namespace psx {
namespace {

struct Rig {
  Scheduler sched;
  InterruptController irq;
  Bus bus{sched, irq};
  // Cycles one fetch charges.
  Cycles fetch(u32 vaddr) {
    Cycles t0 = sched.now();
    u32 w;
    EXPECT_TRUE(bus.fetch(vaddr, w));
    return sched.now() - t0;
  }
};

TEST(BusICache, FillFromTheFetchedWordToTheLineEnd) {
  Rig r;
  EXPECT_EQ(r.fetch(0x80010008), 2u * 4) << "entered at word 2: words 2 and 3";
  EXPECT_EQ(r.fetch(0x8001000C), 0u);
  EXPECT_EQ(r.fetch(0x80010000), 4u * 4) << "word 0 invalid under a matching tag: whole-line refill";
  EXPECT_EQ(r.fetch(0x80010004), 0u);
  EXPECT_EQ(r.fetch(0xA0010004), 4u) << "KSEG1 is never cached";
}

TEST(BusICache, BiosRomFillsAtTheRomReadTime) {
  Rig r;
  const Cycles word = r.bus.read_cycles(Bus::kBiosDelay, 4);
  ASSERT_EQ(word, 24u);
  EXPECT_EQ(r.fetch(0x9FC00000), 4 * word);
  EXPECT_EQ(r.fetch(0x9FC0000C), 0u);
  EXPECT_EQ(r.fetch(0xBFC00000), word);
}

TEST(BusICache, IsolatedStoresWriteTagsOnlyInTagMode) {
  Rig r;
  r.fetch(0x80010000);
  r.bus.write32(0xFFFE0130, 0x800);  // IS1 only: code-word stores, tags untouched
  r.bus.isolated_store(0x00010000, 0);
  EXPECT_EQ(r.fetch(0x80010000), 0u);
  r.bus.write32(0xFFFE0130, 0x804);  // TAG | IS1
  r.bus.isolated_store(0x00010000, 0);
  EXPECT_EQ(r.bus.icache().tag(ICache::line(0x10000)), 0x00010000u);
  EXPECT_EQ(r.fetch(0x80010000), 4u * 4);
}

TEST(BusICache, TagsSurviveASaveState) {
  Rig a;
  a.fetch(0x80010000);
  StateIO w;
  a.bus.do_state(w);
  Rig b;
  StateIO rd(w.buffer().data(), w.buffer().size());
  b.bus.do_state(rd);
  EXPECT_EQ(b.fetch(0x80010004), 0u);
  EXPECT_EQ(b.fetch(0x80020000), 4u * 4);
}

}  // namespace
}  // namespace psx
