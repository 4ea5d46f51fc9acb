// The load shadow (src/core/cpu/cpu.h, at kLoadIssue) at the CPU level: what the model says for
// cases the hardware measurements of tests/roms/cpu_load_timing do not cover, worked out from the
// model's rules: a load takes 2 cycles and its RAM access runs 3..9 after the load starts; an
// instruction after the delay slot reading the register ends no earlier than 9; uncached code
// keeps the fixed times (1 + 4 fetch per instruction, + 4 for a RAM read). Also: a load in
// flight survives a save state.
#include <gtest/gtest.h>

#include "core/bus.h"
#include "core/cpu/cpu.h"
#include "core/gte/gte.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "core/state.h"

namespace psx {

extern template class CpuT<Bus>;

namespace {

constexpr u32 kLwT0 = 0x8C880000;    // lw t0, 0(a0)
constexpr u32 kAdduT1 = 0x01084821;  // addu t1, t0, t0
constexpr u32 kNop = 0;
constexpr u32 kCode = 0x80010000, kData = 0x80020000;

struct Rig {
  Scheduler sched;
  InterruptController irq;
  Gte gte;
  Bus bus{sched, irq};
  Cpu cpu{bus, sched, irq, gte};

  // Places the code at kCode (cached: its line is filled first) or its KSEG1 mirror.
  Rig(std::initializer_list<u32> code, bool cached = true) {
    u32 a = kCode & 0x1FFFFFFF;
    for (u32 w : code) store_le32(bus.ram() + a, w), a += 4;
    store_le32(bus.ram() + (kData & 0x1FFFFFFF), 21);
    cpu.reset();
    const u32 start = cached ? kCode : kCode | 0xA0000000;
    u32 w;
    if (cached)
      for (u32 i = 0; i < code.size(); ++i) bus.fetch(start + 4 * i, w);
    cpu.set_reg(4, kData);
    cpu.set_reg(8, 1);
    cpu.set_pc(start);
  }
  // Cycles `n` instructions take.
  Cycles steps(int n) {
    const Cycles t0 = sched.now();
    for (int i = 0; i < n; ++i) cpu.step();
    return sched.now() - t0;
  }
};

TEST(CpuLoadShadow, UseAfterTheDelaySlotWaitsForTheAccess) {
  Rig r({kLwT0, kNop, kAdduT1});
  EXPECT_EQ(r.steps(3), 9u);
  EXPECT_EQ(r.cpu.reg(9), 42u);
}

TEST(CpuLoadShadow, UseInTheDelaySlotDoesNotWait) {
  Rig r({kLwT0, kAdduT1, kNop});
  EXPECT_EQ(r.steps(3), 2u + 1 + 1);
  EXPECT_EQ(r.cpu.reg(9), 2u) << "the delay slot reads the old value";
}

TEST(CpuLoadShadow, UncachedCodeKeepsFixedTimes) {
  Rig r({kLwT0, kNop, kAdduT1}, false);
  EXPECT_EQ(r.steps(3), 3 * (1 + 4) + 4u);
}

TEST(CpuLoadShadow, ALoadInFlightSurvivesASaveState) {
  Rig a({kLwT0, kNop, kAdduT1});
  a.steps(1);
  StateIO w;
  a.sched.do_state(w), a.bus.do_state(w), a.cpu.do_state(w);
  Rig b({});
  StateIO rd(w.buffer().data(), w.buffer().size());
  b.sched.do_state(rd), b.bus.do_state(rd), b.cpu.do_state(rd);
  EXPECT_EQ(b.steps(2), 9u - 2) << "the use still waits for the access started before saving";
  EXPECT_EQ(b.cpu.reg(9), 42u);
}

}  // namespace
}  // namespace psx
