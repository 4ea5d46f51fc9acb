// SPU reverb against psx-spx "SPU Reverb Formula" worked by hand: one same-side reflection
// write, the all-pass read path with the FIR up-sampler, and the work-area wrap.
#include <gtest/gtest.h>

#include <vector>

#include "spu/reverb.h"

using namespace psx;
using namespace psx::spu;

namespace {
void put(std::vector<u8>& ram, u32 halfword, s16 v) {
  ram[halfword * 2] = static_cast<u8>(v);
  ram[halfword * 2 + 1] = static_cast<u8>(static_cast<u16>(v) >> 8);
}
s16 get(const std::vector<u8>& ram, u32 halfword) {
  return static_cast<s16>(ram[halfword * 2] | ram[halfword * 2 + 1] << 8);
}
}  // namespace

TEST(SpuReverb, SameSideReflectionByHand) {
  std::vector<u8> ram(512 * 1024, 0);
  Reverb rv;
  rv.write_base(0x7000);  // work area from byte 38000h = halfword 1C000h
  const u32 base = 0x1C000;
  rv.regs[Reverb::vWALL] = 0x4000;  // 0.5
  rv.regs[Reverb::vIIR] = 0x4000;   // 0.5
  rv.regs[Reverb::mLSAME] = 0x10;   // halfword base + 40h
  rv.regs[Reverb::dLSAME] = 0x20;   // halfword base + 80h
  put(ram, base + 0x80, 1000);      // [dLSAME]
  put(ram, base + 0x3F, 200);       // [mLSAME-2]
  Reverb::IrqWatch irq;
  rv.tick(0, 0, ram.data(), true, true, irq);  // the left side runs on this cycle
  // [mLSAME] = (Lin + [dLSAME]*vWALL - [mLSAME-2])*vIIR + [mLSAME-2]
  //          = (0 + 500 - 200) * 0.5 + 200 = 350
  EXPECT_EQ(get(ram, base + 0x40), 350);
  // Writes are disabled without the master enable (ATTR bit 7).
  put(ram, base + 0x40, 0);
  Reverb rv2 = Reverb();
  rv2.regs = rv.regs;
  rv2.write_base(0x7000);
  rv2.tick(0, 0, ram.data(), false, true, irq);
  EXPECT_EQ(get(ram, base + 0x40), 0);
}

TEST(SpuReverb, AllPassReadPathThroughTheUpsampler) {
  // With every volume zero, the output is just [mLAPF2-dAPF2] (psx-spx "Reverb Disable").
  // Filling the work area with 1000 makes the 22.05 kHz output constant 1000; the up-sampler
  // then gives 1000 on the centre-tap cycle and (sum of even taps = 16382) * 1000 >> 14 = 999 on
  // the other.
  std::vector<u8> ram(512 * 1024, 0);
  Reverb rv;
  rv.write_base(0xF000);
  for (u32 hw = 0xF000 * 4; hw < 0x40000; ++hw) put(ram, hw, 1000);
  rv.regs[Reverb::mLAPF2] = rv.regs[Reverb::mRAPF2] = 0x100;
  rv.regs[Reverb::dAPF2] = 0x40;
  Reverb::IrqWatch irq;
  for (int i = 0; i < 100; ++i) rv.tick(0, 0, ram.data(), false, true, irq);
  StereoSample a = rv.tick(0, 0, ram.data(), false, true, irq);  // left computes, right holds
  StereoSample b = rv.tick(0, 0, ram.data(), false, true, irq);  // right computes, left holds
  EXPECT_EQ(a.left, 999);
  EXPECT_EQ(a.right, 1000);
  EXPECT_EQ(b.left, 1000);
  EXPECT_EQ(b.right, 999);
}

TEST(SpuReverb, IrqWatchSeesWorkAreaAccesses) {
  std::vector<u8> ram(512 * 1024, 0);
  Reverb rv;
  rv.write_base(0xF000);
  rv.regs[Reverb::mLSAME] = 0x10;
  Reverb::IrqWatch irq{true, 0xF000 + 0x10, false};
  rv.tick(0, 0, ram.data(), false, true, irq);
  EXPECT_TRUE(irq.hit);
}
