// Root counter tests. Expected counts come from psx-spx "Timers" and "GPU Timings" and the clock
// ratios: the dot clock is the video clock (NTSC 53.693175 MHz after reset) over the divider, 10
// video clocks per dot in 256-pixel mode; a COUNT write holds the counter for one extra clock,
// and a reset at COMP holds 0 for two clocks. After a MODE write the very first tick counts: on
// hardware (pcsx-redux src/mips/tests/timers) timers 0 and 1 reset together measure 341 dots a
// line in 256-pixel NTSC mode, which a held first HBlank would turn into 348.
#include <gtest/gtest.h>

#include "core/irq.h"
#include "core/scheduler.h"
#include "core/timers.h"

namespace psx {
namespace {

constexpr u32 kCount = 0, kMode = 4, kTarget = 8;
constexpr u32 reg(u32 timer, u32 r) { return timer * 0x10 + r; }

class TimersTest : public ::testing::Test {
 protected:
  Scheduler sched;
  InterruptController irq;
  Timers t{sched, irq};

  void SetUp() override { irq.write(4, 0x7FF); }
  // Runs the timeline to absolute cycle `when`, dispatching events on their cycle.
  void at(Cycles when) {
    while (sched.now() < when) {
      Cycles next = std::min(when, sched.next_deadline());
      if (next > sched.now()) sched.advance(next - sched.now());
      sched.run_due_events();
    }
    sched.run_due_events();
  }
  u32 count(u32 i) { return t.io_read(reg(i, kCount), 2); }
  u32 mode(u32 i) { return t.io_read(reg(i, kMode), 2); }
  void set_mode(u32 i, u32 v) { t.io_write(reg(i, kMode), v, 2); }
  bool irq_line(u32 i) { return irq.stat() & (1u << (4 + i)); }
  void ack() { irq.write(0, 0); }
};

TEST_F(TimersTest, SysclockCountsFromModeWrite) {
  set_mode(2, 0);
  // The first clock after a MODE write counts (see the header comment).
  EXPECT_EQ(count(2), 0u);
  at(1);
  EXPECT_EQ(count(2), 1u);
  at(2);
  EXPECT_EQ(count(2), 2u);
  at(1000);
  EXPECT_EQ(count(2), 1000u);
}

TEST_F(TimersTest, ZretSequenceHoldsZeroAfterComp) {
  t.io_write(reg(0, kTarget), 1, 2);
  set_mode(0, Timers::kZret);
  // psx-spx "Reset and Wrap", COMP = 1 with ZRET: 0, 0, 1, 0, 0, 1 once counting, the reset to 0
  // held a tick; from the MODE write the first tick counts.
  const u32 expect[] = {0, 1, 0, 0, 1, 0, 0, 1, 0};
  for (u32 c = 0; c < 9; ++c) {
    at(c);
    EXPECT_EQ(count(0), expect[c]) << "cycle " << c;
  }
}

TEST_F(TimersTest, ZretLongIntervalWithoutIrq) {
  t.io_write(reg(1, kTarget), 9, 2);
  set_mode(1, Timers::kZret);
  // Value(t) = t up to COMP at t=9; after that a period of COMP+2 = 11 starting at t=10 with
  // values 0,0,1..9. t=1004: (1004-10) mod 11 = 4 -> 3.
  at(1004);
  EXPECT_EQ(count(1), 3u);
  EXPECT_NE(mode(1) & Timers::kEquf, 0u);
  EXPECT_EQ(mode(1) & Timers::kOvff, 0u);  // never reached 0xFFFF
}

TEST_F(TimersTest, TargetIrqRepeatPulseOnExactCycle) {
  t.io_write(reg(0, kTarget), 50, 2);
  set_mode(0, Timers::kZret | Timers::kCmp | Timers::kRept);
  // COMP reached at t = 50, then every 52 clocks (0 held for two).
  at(49);
  EXPECT_FALSE(irq_line(0));
  at(50);
  EXPECT_TRUE(irq_line(0));
  EXPECT_NE(mode(0) & Timers::kIntf, 0u);  // pulse: INTF reads back 1
  ack();
  at(101);
  EXPECT_FALSE(irq_line(0));
  at(102);
  EXPECT_TRUE(irq_line(0));
}

TEST_F(TimersTest, ToggleModeRaisesEverySecondEvent) {
  t.io_write(reg(1, kTarget), 50, 2);
  set_mode(1, Timers::kZret | Timers::kCmp | Timers::kRept | Timers::kLevl);
  EXPECT_NE(mode(1) & Timers::kIntf, 0u);  // set by the MODE write
  at(50);
  EXPECT_TRUE(irq_line(1));
  EXPECT_EQ(mode(1) & Timers::kIntf, 0u);
  ack();
  at(102);
  EXPECT_FALSE(irq_line(1));  // INTF went 0 -> 1: no IRQ
  EXPECT_NE(mode(1) & Timers::kIntf, 0u);
  at(154);
  EXPECT_TRUE(irq_line(1));
}

TEST_F(TimersTest, OneShotFiresOnceUntilModeWrite) {
  t.io_write(reg(2, kTarget), 50, 2);
  set_mode(2, Timers::kZret | Timers::kCmp);
  at(51);
  EXPECT_TRUE(irq_line(2));
  ack();
  at(500);
  EXPECT_FALSE(irq_line(2));
  EXPECT_NE(mode(2) & Timers::kEquf, 0u);  // the counter keeps counting and reaching COMP
}

TEST_F(TimersTest, ReachedFlagsClearOnRead) {
  t.io_write(reg(0, kTarget), 5, 2);
  set_mode(0, 0);
  at(6);
  u32 m = mode(0);
  EXPECT_NE(m & Timers::kEquf, 0u);
  EXPECT_EQ(mode(0) & Timers::kEquf, 0u);
}

TEST_F(TimersTest, OverflowIrqAndCountAboveTarget) {
  set_mode(0, Timers::kOvfl | Timers::kRept);
  t.io_write(reg(0, kCount), 0xFFF0, 2);
  // COUNT write holds one clock: 0xFFFF is reached 1 + 15 clocks later.
  at(15);
  EXPECT_FALSE(irq_line(0));
  at(16);
  EXPECT_TRUE(irq_line(0));
  EXPECT_NE(mode(0) & Timers::kOvff, 0u);
  at(17);
  EXPECT_EQ(count(0), 0u);  // the wrap holds 0 for only one clock
  at(18);
  EXPECT_EQ(count(0), 1u);
}

TEST_F(TimersTest, CountAboveTargetRunsThroughWrapFirst) {
  t.io_write(reg(1, kTarget), 10, 2);
  set_mode(1, Timers::kZret | Timers::kCmp | Timers::kRept);
  t.io_write(reg(1, kCount), 20, 2);
  // 1 held clock + (0xFFFF - 20) to 0xFFFF + 1 to wrap + 10 to COMP.
  Cycles reach = 1 + (0xFFFF - 20) + 1 + 10;
  at(reach - 1);
  EXPECT_FALSE(irq_line(1));
  at(reach);
  EXPECT_TRUE(irq_line(1));
}

TEST_F(TimersTest, Timer2DividesBy8) {
  set_mode(2, Timers::kPscl);
  // Ticks at t = 8, 16, ...
  at(807);
  EXPECT_EQ(count(2), 100u);
  at(808);
  EXPECT_EQ(count(2), 101u);
}

TEST_F(TimersTest, Timer0Dotclock) {
  set_mode(0, Timers::kExtc);
  // 256-pixel mode: a dot per 10 NTSC video clocks = 338688000/53693175 CPU clocks. 7000 clocks:
  // floor(7000 * 53693175 / 338688000) = floor(1109.7) = 1109 dots.
  at(7000);
  EXPECT_EQ(count(0), 1109u);
  // Dot k falls on cycle ceil(k * 338688000 / 53693175): dot 1110 at 7002.
  at(7001);
  EXPECT_EQ(count(0), 1109u);
  at(7002);
  EXPECT_EQ(count(0), 1110u);
}

TEST_F(TimersTest, Timer0DotclockFollowsDivider) {
  t.dot_clock_changed(53693175, 8);  // 320-pixel NTSC
  set_mode(0, Timers::kExtc);
  // psx-spx: 320pix/NTSC has 3413/8 = 426.625 dots per 3413-cycle line, so 8 lines are 3413
  // dots; 8 lines are 8 * 3413 * 33868800 / 53693175 = 17222.93 CPU cycles.
  at(17222);
  EXPECT_EQ(count(0), 3412u);
  at(17223);
  EXPECT_EQ(count(0), 3413u);
}

TEST_F(TimersTest, Timer0DotclockPal) {
  t.dot_clock_changed(53203425, 8);  // 320-pixel PAL
  set_mode(0, Timers::kExtc);
  // psx-spx: 320pix/PAL has 3406/8 = 425.75 dots per 3406-cycle line: 4 lines are 1703 dots in
  // 4 * 3406 * 33868800 / 53203425 = 8672.91 CPU cycles.
  at(8672);
  EXPECT_EQ(count(0), 1702u);
  at(8673);
  EXPECT_EQ(count(0), 1703u);
}

// A video clock whose HBlanks start at cycles 100, 220, 340, ... (every 120 cycles; the real
// line times are tested in gpu_video_test.cpp). Timer 1 asks it for them in closed form.
class EvenHblanks : public VideoClock {
 public:
  bool hblank_now() override { return false; }
  void hblank_wanted_changed() override {}
  u64 hblanks_by(Cycles t) const override { return t < 100 ? 0 : (t - 100) / 120 + 1; }
  Cycles hblank_time(u64 n) const override { return 100 + (n - 1) * 120; }
};

TEST_F(TimersTest, Timer1CountsHblanks) {
  EvenHblanks video;
  t.set_video_clock(&video);
  at(50);
  set_mode(1, Timers::kExtc);
  at(579);
  EXPECT_EQ(count(1), 4u);  // HBlanks at 100, 220, 340, 460
  at(580);
  EXPECT_EQ(count(1), 5u);
  at(580 + 10 * 120);
  EXPECT_EQ(count(1), 15u);
  // From a MODE write on (at 1780, an HBlank's cycle), only later HBlanks count: 1900 and 2020.
  set_mode(1, Timers::kExtc);
  at(580 + 12 * 120);
  EXPECT_EQ(count(1), 2u);
}

TEST_F(TimersTest, Timer1HblankIrqOnTheHblankThatReachesComp) {
  // COMP 3: the 3rd HBlank after the MODE write at 50 (at 340) reaches it, and the IRQ comes on
  // that cycle, from the timers' own event (no event per HBlank).
  EvenHblanks video;
  t.set_video_clock(&video);
  at(50);
  t.io_write(reg(1, kTarget), 3, 2);
  set_mode(1, Timers::kExtc | Timers::kCmp | Timers::kZret | Timers::kRept);
  EXPECT_EQ(sched.when(sched.find("timers")), 340u);
  at(339);
  EXPECT_FALSE(irq_line(1));
  at(340);
  EXPECT_TRUE(irq_line(1));
  ack();
  // A reset at COMP holds 0 for two ticks (psx-spx "Reset and Wrap"): the HBlanks at 460 and 580
  // leave it at 0, those at 700, 820 and 940 count to 3.
  EXPECT_EQ(sched.when(sched.find("timers")), 940u);
  at(939);
  EXPECT_FALSE(irq_line(1));
  EXPECT_EQ(count(1), 2u);
  at(940);
  EXPECT_TRUE(irq_line(1));
}

TEST_F(TimersTest, SyncMode0PausesDuringHblank) {
  set_mode(0, Timers::kGatf | (0 << 1));
  at(100);
  t.hblank_changed(true);
  at(150);
  t.hblank_changed(false);
  at(250);
  EXPECT_EQ(count(0), 200u);  // 100 + 100 counted clocks
}

TEST_F(TimersTest, SyncMode1ResetsAtHblank) {
  set_mode(0, Timers::kGatf | (1 << 1));
  at(100);
  t.hblank_changed(true);
  at(150);
  EXPECT_EQ(count(0), 50u);
}

TEST_F(TimersTest, SyncMode2CountsOnlyInsideHblank) {
  set_mode(0, Timers::kGatf | (2 << 1));
  at(100);
  EXPECT_EQ(count(0), 0u);
  t.hblank_changed(true);
  at(130);
  t.hblank_changed(false);
  at(200);
  EXPECT_EQ(count(0), 30u);
}

TEST_F(TimersTest, SyncMode3WaitsForFirstBlank) {
  set_mode(1, Timers::kGatf | (3 << 1));
  at(100);
  EXPECT_EQ(count(1), 0u);
  t.vblank_changed(true);
  at(110);
  t.vblank_changed(false);
  at(200);
  EXPECT_EQ(count(1), 100u);  // free from t=100
}

TEST_F(TimersTest, Timer1SyncMode0PausesDuringVblank) {
  set_mode(1, Timers::kGatf);
  at(100);
  t.vblank_changed(true);
  at(300);
  t.vblank_changed(false);
  at(400);
  EXPECT_EQ(count(1), 200u);
}

TEST_F(TimersTest, Timer2SyncModes) {
  set_mode(2, Timers::kGatf | (0 << 1));  // stop
  at(100);
  EXPECT_EQ(count(2), 0u);
  set_mode(2, Timers::kGatf | (1 << 1));  // free run
  at(200);
  EXPECT_EQ(count(2), 100u);
}

TEST_F(TimersTest, SaveStateRoundTripMidCount) {
  t.io_write(reg(0, kTarget), 300, 2);
  set_mode(0, Timers::kZret | Timers::kCmp | Timers::kRept | Timers::kExtc);
  at(500);
  StateIO out;
  t.do_state(out);
  Scheduler sched2;
  InterruptController irq2;
  Timers t2{sched2, irq2};
  sched2.advance(500);
  StateIO in(out.buffer().data(), out.buffer().size());
  t2.do_state(in);
  EXPECT_TRUE(in.at_end());
  sched.advance(2500);
  sched2.advance(2500);
  EXPECT_EQ(t2.io_read(0, 2), t.io_read(0, 2));
  EXPECT_EQ(t2.io_read(4, 2), t.io_read(4, 2));
}

}  // namespace
}  // namespace psx
