// Memory Control read timing (psx-spx "Memory Control", corrected by JaCzekanski's ps1-tests
// cpu/access-time hardware log: see memory_control.h): the documented power-on Delay/Size
// settings against the log's figures, psx-spx's floors, and the Bus charging those times.
#include <gtest/gtest.h>

#include "core/bus.h"
#include "core/irq.h"
#include "core/memory_control.h"
#include "core/scheduler.h"

namespace psx {
namespace {

constexpr u32 kCom = 0x00031125;  // COM0 = 5, COM1 = 2, COM2 = 1, COM3 = 1

// Each figure below is a row of the hardware log (ps1-tests cpu/access-time psx.log, kept in
// tests/data/ps1-tests/cpu-access-time.log), rounded to whole cycles, with the Delay/Size value
// the BIOS leaves in the region's register.
TEST(MemoryControl, EightBitBusMatchesHardwareLog) {
  // BIOS ROM and expansion 1, 0x0013243F: read delay 3, COM2 (1), 8-bit bus. FIRST = 3 + 4 = 7;
  // SEQ = 3 + 2 + 1 = 6. Log: 7.6, 12.94, 24.94 (BIOS), 6.94, 13.7, 25.7 (EXPANSION1).
  EXPECT_EQ(memory_read_cycles(0x0013243F, kCom, 1), 7u);
  EXPECT_EQ(memory_read_cycles(0x0013243F, kCom, 2), 13u);
  EXPECT_EQ(memory_read_cycles(0x0013243F, kCom, 4), 25u);
  // Expansion 2, 0x00070777: read delay 7, COM0 (5), COM1, COM2 (1). FIRST = 11; SEQ =
  // 7 + 2 + 5 + 1 = 15. Log: 10.99, 25.99, 55.98.
  EXPECT_EQ(memory_read_cycles(0x00070777, kCom, 1), 11u);
  EXPECT_EQ(memory_read_cycles(0x00070777, kCom, 2), 26u);
  EXPECT_EQ(memory_read_cycles(0x00070777, kCom, 4), 56u);
  // CD-ROM, 0x00020843: read delay 4, COM3 (MIN 1, below both). FIRST = 8, SEQ = 6. Log: 8.0,
  // 14.0, 25.93.
  EXPECT_EQ(memory_read_cycles(0x00020843, kCom, 1), 8u);
  EXPECT_EQ(memory_read_cycles(0x00020843, kCom, 2), 14u);
  EXPECT_EQ(memory_read_cycles(0x00020843, kCom, 4), 26u);
}

TEST(MemoryControl, SixteenBitBusMatchesHardwareLog) {
  // Expansion 3, 0x00003022: read delay 2, no COM, 16-bit bus. FIRST = 6, SEQ = 4: bytes and
  // halfwords take one bus cycle, words two. Log: 6.7, 6.1, 9.95.
  EXPECT_EQ(memory_read_cycles(0x00003022, kCom, 1), 6u);
  EXPECT_EQ(memory_read_cycles(0x00003022, kCom, 2), 6u);
  EXPECT_EQ(memory_read_cycles(0x00003022, kCom, 4), 10u);
  // SPU, 0x200931E1: read delay 14, COM0 (5), 16-bit bus. FIRST = 18. Log: 17.99, 17.99 (its
  // 32-bit row is an unaligned LWL/LWR pair, not one word read: below).
  EXPECT_EQ(memory_read_cycles(0x200931E1, kCom, 1), 18u);
  EXPECT_EQ(memory_read_cycles(0x200931E1, kCom, 2), 18u);
}

// LWL/LWR read only the bus units that hold the bytes they merge (Mednafen's cpu.cpp reads 8,
// 16 or 24 bits for them): ps1-tests' 32-bit SPU row, an LWL at offset 1 and an LWR at offset 2
// (bytes 0..1 and 2..3 of two words), costs 38.94 on the console, 18 + 18 and 3 cycles of the
// accesses' tails (the CPU's, cpu.h kIoTail), where two whole-word reads would take 2 x 39.
TEST(MemoryControl, PartialWordReadsTakeTheUnitsHoldingTheirBytes) {
  EXPECT_EQ(memory_bus_units(0x200931E1, 0, 2), 1u);  // 16-bit bus: bytes 0..1, one halfword
  EXPECT_EQ(memory_bus_units(0x200931E1, 2, 2), 1u);
  EXPECT_EQ(memory_bus_units(0x200931E1, 1, 3), 2u);  // bytes 1..3 straddle both halfwords
  EXPECT_EQ(memory_bus_units(0x200931E1, 3, 1), 1u);
  EXPECT_EQ(memory_bus_units(0x0013243F, 0, 3), 3u);  // 8-bit bus: one unit a byte
  EXPECT_EQ(memory_read_unit_cycles(0x200931E1, kCom, memory_bus_units(0x200931E1, 0, 2)), 18u);
  EXPECT_EQ(memory_read_unit_cycles(0x200931E1, kCom, 2), 39u);  // FIRST 18 + SEQ 14 + 2 + 5
  EXPECT_EQ(memory_read_unit_cycles(0x0013243F, kCom, 3), 19u);  // BIOS: 7 + 2 x 6
}

TEST(MemoryControl, Com3Minimum) {
  // psx-spx's floors, which no setting above reaches: FIRST >= MIN + 6, SEQ >= MIN + 2, MIN =
  // COM3 with the pre-strobe period (bit 11). The fastest setting is held at FIRST = 6; the
  // CD-ROM's with COM3 = 15 at FIRST 21, SEQ 17.
  EXPECT_EQ(memory_read_cycles(0x00000000, kCom, 1), 6u);
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
  // Reprogram 0x1F801010: read delay 0, no COM, 16-bit bus: FIRST max(4, 6) = 6, SEQ 2, so a
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
