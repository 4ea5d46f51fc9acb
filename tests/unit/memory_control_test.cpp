// Memory Control read timing (psx-spx "Memory Control"): the access-time rule applied to the
// documented power-on Delay/Size settings, checked against the rule's arithmetic and against
// JaCzekanski's ps1-tests cpu/access-time hardware log; and the Bus charging those times.
#include <gtest/gtest.h>

#include "core/bus.h"
#include "core/irq.h"
#include "core/memory_control.h"
#include "core/scheduler.h"

namespace psx {
namespace {

constexpr u32 kCom = 0x00031125;  // COM0 = 5, COM1 = 2, COM2 = 1, COM3 = 1

TEST(MemoryControl, BiosRomMatchesHardwareLog) {
  // 0x0013243F: read delay 3, COM2 (1), 8-bit bus. FIRST = 1, +1 (below 6) = 2, + 3 + 2 = 7;
  // SEQ = 1 + 3 + 2 = 6. Hardware (ps1-tests cpu/access-time psx.log, BIOS): 7, 13, 25.
  EXPECT_EQ(memory_read_cycles(0x0013243F, kCom, 1), 7u);
  EXPECT_EQ(memory_read_cycles(0x0013243F, kCom, 2), 7u + 6);
  EXPECT_EQ(memory_read_cycles(0x0013243F, kCom, 4), 7u + 3 * 6);
}

TEST(MemoryControl, SixteenBitBusMatchesHardwareLog) {
  // EXP3 0x00003022: read delay 2, no COM, 16-bit bus. FIRST = 0 + 1 + 2 + 2 = 5, raised to
  // MIN + 6 = 6; SEQ = 2 + 2 = 4. Bytes and halfwords take one bus cycle, words two: 6, 6, 10,
  // as the hardware log has for EXPANSION3.
  EXPECT_EQ(memory_read_cycles(0x00003022, kCom, 1), 6u);
  EXPECT_EQ(memory_read_cycles(0x00003022, kCom, 2), 6u);
  EXPECT_EQ(memory_read_cycles(0x00003022, kCom, 4), 10u);
  // The fastest setting (low 16 bits zero) is held at FIRST = MIN + 6 = 6.
  EXPECT_EQ(memory_read_cycles(0x00000000, kCom, 1), 6u);
  // SPU 0x200931E1: read delay 14, COM0 (5 - 1 = 4), 16-bit bus. FIRST = 4 + 1 + 14 + 2 = 21,
  // SEQ = 4 + 14 + 2 = 20.
  EXPECT_EQ(memory_read_cycles(0x200931E1, kCom, 2), 21u);
  EXPECT_EQ(memory_read_cycles(0x200931E1, kCom, 4), 41u);
}

TEST(MemoryControl, Com3Minimum) {
  // CD-ROM 0x00020843: read delay 4, COM3 -> MIN = 1; FIRST = 1 + 4 + 2 = 7 (>= MIN + 6),
  // SEQ = 6 (>= MIN + 2). A large COM3 raises both: COM3 = 15 gives FIRST 21, SEQ 17.
  EXPECT_EQ(memory_read_cycles(0x00020843, kCom, 1), 7u);
  EXPECT_EQ(memory_read_cycles(0x00020843, kCom, 4), 7u + 3 * 6);
  EXPECT_EQ(memory_read_cycles(0x00020843, 0x0000F000, 1), 21u);
  EXPECT_EQ(memory_read_cycles(0x00020843, 0x0000F000, 2), 21u + 17);
}

TEST(MemoryControl, BusChargesBiosDelayRegister) {
  Scheduler sched;
  InterruptController irq;
  Bus bus(sched, irq);
  u32 v;
  // Default BIOS setting: 25 cycles for a word, of which the load's own cycle is the CPU's.
  Cycles t0 = sched.now();
  ASSERT_TRUE(bus.read32(0xBFC00000, v));
  EXPECT_EQ(sched.now() - t0, 24u);
  t0 = sched.now();
  ASSERT_TRUE(bus.read8(0xBFC00000, v));
  EXPECT_EQ(sched.now() - t0, 6u);
  // Reprogram 0x1F801010: read delay 0, no COM, 16-bit bus: FIRST max(3, 6) = 6, SEQ 2, so a
  // word is 8 cycles.
  ASSERT_TRUE(bus.write32(0x1F801010, 0x00131000));
  t0 = sched.now();
  ASSERT_TRUE(bus.read32(0xBFC00000, v));
  EXPECT_EQ(sched.now() - t0, 7u);
  // RAM and the on-chip I/O ports keep their fixed times (hardware log: 5 and 3 cycles a load).
  t0 = sched.now();
  ASSERT_TRUE(bus.read32(0x80000000, v));
  EXPECT_EQ(sched.now() - t0, 4u);
  t0 = sched.now();
  ASSERT_TRUE(bus.read32(0x1F801070, v));
  EXPECT_EQ(sched.now() - t0, 2u);
}

}  // namespace
}  // namespace psx
