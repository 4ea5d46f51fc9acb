// GTE commands and division with expected values worked by hand from psx-spx ("GTE Division
// Inaccuracy", "GTE Coordinate Calculation Commands", "GTE Saturation", command timing).
#include <gtest/gtest.h>

#include "core/gte/gte.h"
#include "core/gte/gte_divide.h"

namespace psx {
namespace {

constexpr u32 kRtps = 0x01, kRtpt = 0x30, kNcdt = 0x16, kAvsz3 = 0x2D, kMvmva = 0x12;
constexpr u32 kSf = 1u << 19;
constexpr u32 kFlag = 63;

TEST(GteDivide, UnrTableEndpointsAndMiddle) {
  ASSERT_EQ(kGteUnrTable.size(), 257u);
  // max(0, (40000h/(i+100h)+1)/2 - 101h):
  EXPECT_EQ(kGteUnrTable[0], 0xFF);     // 40000h/100h = 400h; 401h/2 = 200h; 200h-101h = FFh
  EXPECT_EQ(kGteUnrTable[0x80], 0x54);  // 262144/384 = 682; 683/2 = 341; 341-257 = 84
  EXPECT_EQ(kGteUnrTable[0x100], 0x00);  // 40000h/200h = 200h; 201h/2 = 100h; 100h-101h < 0
}

TEST(GteDivide, ExactQuotients) {
  // 100h/100h: z=7, n=d=8000h, u=FFh+101h=200h, d=(2000080h-1000000h)>>8=10000h,
  // d=(80h+2000000h)>>8=20000h, (8000h*20000h+8000h)>>16 = 10000h (1.0).
  EXPECT_EQ(gte_divide(0x100, 0x100), 0x10000u);
  // 1000h/2000h: z=2, n=4000h, d=8000h -> 20000h as above; (4000h*20000h+8000h)>>16 = 8000h.
  EXPECT_EQ(gte_divide(0x1000, 0x2000), 0x8000u);
}

TEST(GteDivide, OverflowUnlessHBelowTwiceSz3) {
  EXPECT_TRUE(gte_divide_overflows(0x200, 0x100));
  EXPECT_FALSE(gte_divide_overflows(0x1FF, 0x100));
  EXPECT_TRUE(gte_divide_overflows(0, 0));  // SZ3 = 0 always overflows
}

// RT = identity (1000h = 1.0), TR = 0, H = 1000, OFX/OFY = (160,120) in 16.16, sf=1.
Gte identity_camera() {
  Gte g;
  g.write_control(0, 0x1000);  // RT11
  g.write_control(2, 0x1000);  // RT22
  g.write_control(4, 0x1000);  // RT33
  g.write_control(24, 160u << 16);
  g.write_control(25, 120u << 16);
  g.write_control(26, 1000);
  return g;
}

TEST(GteCommands, RtpsProjectsAPoint) {
  Gte g = identity_camera();
  g.write_data(0, (50u << 16) | 100u);  // V0 = (100, 50, 1000)
  g.write_data(1, 1000);
  EXPECT_EQ(g.execute(kRtps | kSf), 15u);
  // MAC = RT*V SAR 12 = (100, 50, 1000); SZ3 = 1000.
  // H/SZ3 = 1000/1000: z=6, d=n=FA00h, index (FA00h-7FC0h)>>7 = F4h, table = 5, u = 106h,
  // d = (2000080h - FA00h*106h)>>8 = 65572, d = (80h + 65572*262)>>8 = 67109,
  // (FA00h*67109 + 8000h)>>16 = 10000h, so SX = 100+160 = 260, SY = 50+120 = 170.
  EXPECT_EQ(g.read_data(25), 100u);
  EXPECT_EQ(g.read_data(26), 50u);
  EXPECT_EQ(g.read_data(27), 1000u);
  EXPECT_EQ(g.read_data(19), 1000u);
  EXPECT_EQ(g.read_data(14), (170u << 16) | 260u);
  EXPECT_EQ(g.read_register(kFlag), 0u);
}

TEST(GteCommands, RtpsDivideOverflowAtZeroDepth) {
  Gte g = identity_camera();
  g.write_data(0, 1);  // V0 = (1, 0, 0): SZ3 = 0, so H >= 2*SZ3
  g.execute(kRtps | kSf);
  // Quotient 1FFFFh, IR1 = 1: SX = (1FFFFh*1 + A00000h)>>16 = A1FFFFh>>16 = 161.
  EXPECT_EQ(g.read_data(14) & 0xFFFF, 161u);
  EXPECT_EQ(g.read_register(kFlag), Gte::kFlagError | Gte::kFlagDivide);
}

TEST(GteCommands, MacOverflowBeyond44Bits) {
  Gte g;
  g.write_control(5, 0x7FFFFFFF);  // TRX
  g.write_control(0, 0x7FFF);      // RT11
  g.write_data(0, 0x7FFF);         // VX0
  // MVMVA sf=1, RT*V0+TR: 7FFFFFFFh SHL 12 + 7FFFh*7FFFh = 7FFFFFFF000h + 3FFF0001h
  // = 8003FFEF001h > 7FFFFFFFFFFh: FLAG 30; it wraps to -7FFC0010FFFh, SAR 12 = -7FFC0011h,
  // so MAC1 = 8003FFEFh and IR1 saturates to -8000h (FLAG 24).
  g.execute(kMvmva | kSf);
  EXPECT_EQ(g.read_data(25), 0x8003FFEFu);
  EXPECT_EQ(g.read_data(9), 0xFFFF8000u);
  EXPECT_EQ(g.read_register(kFlag), Gte::kFlagError | Gte::kFlagMac1Pos | Gte::kFlagIr1);
}

TEST(GteCommands, Avsz3AveragesScreenZ) {
  Gte g;
  g.write_data(17, 100);
  g.write_data(18, 200);
  g.write_data(19, 300);
  g.write_control(29, 0x555);  // ZSF3 ~ 1/3 in 4.12
  EXPECT_EQ(g.execute(kAvsz3), 5u);
  // MAC0 = 555h * 600 = 1365*600 = 819000; OTZ = 819000 >> 12 = 199.
  EXPECT_EQ(g.read_data(24), 819000u);
  EXPECT_EQ(g.read_data(7), 199u);
}

TEST(GteCommands, CycleCounts) {
  Gte g;
  EXPECT_EQ(g.execute(kRtpt | kSf), 23u);
  EXPECT_EQ(g.execute(kNcdt | kSf), 44u);
  EXPECT_EQ(Gte::command_cycles(0x3F), 39u);  // NCCT
  EXPECT_EQ(Gte::command_cycles(0x28), 5u);   // SQR
  // NCDT (44 cycles in psx-spx's summary) is the longest of all 64 opcodes.
  EXPECT_EQ(Gte::kLongestCommandCycles, 44u);
  for (u32 opcode = 0; opcode < 64; ++opcode) EXPECT_LE(Gte::command_cycles(opcode), 44u) << opcode;
}

}  // namespace
}  // namespace psx
