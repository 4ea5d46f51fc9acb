// SPU reverb against psx-spx "SPU Reverb Formula" worked by hand: one same-side reflection
// write, the all-pass read path with the FIR up-sampler, and the work-area wrap (every access's
// address, seen through the IRQ watch, for work areas from 8 bytes to all of sound RAM).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "spu/reverb.h"
#include "spu_test_util.h"

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

TEST(SpuReverb, InputFilterReachesBack38Inputs) {
  // psx-spx "Reverb Buffer Resampling": the 39-tap filter's outermost tap is -0001h, 38 inputs
  // back. An impulse of 4000h on the left input in tick 1 (the left side runs on odd ticks)
  // reaches the left 22.05 kHz input in tick 39 as (4000h * -1) >> 15 = -1 and is gone by tick
  // 41. With vLIN = vIIR = 7FFFh and an empty work area, the same-side reflection writes
  // [mLSAME] = (Lin * vLIN) * vIIR = -1 there (>> 15 floors: -7FFFh >> 15 = -1), else 0. The
  // buffer address in tick t is the base + (t-1)/2 halfwords.
  std::vector<u8> ram(512 * 1024, 0);
  Reverb rv;
  rv.write_base(0xF000);
  const u32 base = 0xF000 * 4;
  rv.regs[Reverb::vLIN] = rv.regs[Reverb::vIIR] = 0x7FFF;
  rv.regs[Reverb::mLSAME] = 0x10;  // 40h halfwords on
  Reverb::IrqWatch irq;
  s16 written[2] = {};
  for (u32 t = 1; t <= 41; ++t) {
    if (t == 39 || t == 41) std::fill(ram.begin(), ram.end(), 0);  // the earlier ticks' writes
    rv.tick(t == 1 ? 0x4000 : 0, 0, ram.data(), true, false, irq);
    if (t == 39) written[0] = get(ram, base + 19 + 0x40);
    if (t == 41) written[1] = get(ram, base + 20 + 0x40);
  }
  EXPECT_EQ(written[0], -1);
  EXPECT_EQ(written[1], 0);
}

namespace {

// psx-spx "SPU Reverb Formula": each of a side's 14 accesses is at a register-relative offset
// (registers in 8-byte units = 4 halfwords) from the buffer address, wrapped into the work area
// ESA*4 .. 3FFFFh halfwords as a true modulo. Returns the 8-byte units touched by `side`.
std::set<u32> expected_units(const Reverb& rv, u32 side, u32 current) {
  auto reg = [&](u32 r) { return static_cast<s64>(rv.regs[r]) * 4; };
  const u32 other = side ^ 1;
  const s64 rels[14] = {
      reg(Reverb::mLSAME + side) - 1, reg(Reverb::dLSAME + side), reg(Reverb::mLSAME + side),
      reg(Reverb::mLDIFF + side) - 1, reg(Reverb::dLDIFF + other), reg(Reverb::mLDIFF + side),
      reg(Reverb::mLCOMB1 + side), reg(Reverb::mLCOMB2 + side), reg(Reverb::mLCOMB3 + side),
      reg(Reverb::mLCOMB4 + side), reg(Reverb::mLAPF1 + side) - reg(Reverb::dAPF1),
      reg(Reverb::mLAPF1 + side), reg(Reverb::mLAPF2 + side) - reg(Reverb::dAPF2), reg(Reverb::mLAPF2 + side)};
  const s64 start = static_cast<s64>(rv.base()) * 4, size = 0x40000 - start;
  std::set<u32> units;
  for (s64 rel : rels) {
    const s64 off = ((static_cast<s64>(current) - start + rel) % size + size) % size;
    units.insert(static_cast<u32>((start + off) >> 2));
  }
  return units;
}

}  // namespace

TEST(SpuReverb, EveryAccessWrapsInsideTheWorkArea) {
  // Random registers (delays up to the whole of RAM, m-d offsets negative or past the area) on
  // work areas from one 8-byte unit (ESA FFFFh) to all of sound RAM (ESA 0). In each tick every
  // expected unit, its neighbours and a few random units of the area are watched on a copy of
  // the reverb: exactly the expected ones are hit. The buffer address moves one halfword after
  // each right-side tick and wraps to ESA (psx-spx: MAX(mBASE, (addr+2) AND 7FFFEh) in bytes).
  std::vector<u8> ram(512 * 1024, 0);
  u32 x = 12345;
  auto next = [&](u32 n) {
    x = x * 1664525u + 1013904223u;
    return (x >> 8) % n;
  };
  for (u16 esa : {0xFFFF, 0xFFFE, 0xFFF0, 0xFF00, 0xF000, 0x8000, 0x0000}) {
    Reverb rv;
    rv.write_base(esa);
    for (u16& r : rv.regs) r = static_cast<u16>(next(4) == 0 ? next(0x10000) : next(0x10000 - esa + 1) * (next(2) + 1));
    const u32 start = esa * 4u, units_in_area = 0x10000 - esa;
    u32 current = start;
    for (u32 t = 0; t < 400; ++t) {
      const u32 side = t & 1;
      const std::set<u32> expected = expected_units(rv, side, current);
      std::set<u32> watched = expected;
      for (u32 u : expected) watched.insert({u - 1, u + 1});
      for (u32 k = 0; k < 4; ++k) watched.insert(esa + next(units_in_area));
      for (u32 u : watched) {
        Reverb copy = rv;
        Reverb::IrqWatch irq{true, u, false};
        copy.tick(static_cast<s32>(next(0x10000)) - 0x8000, 0, ram.data(), next(2) == 0, false, irq);
        ASSERT_EQ(irq.hit, expected.count(u) == 1) << "ESA " << esa << " tick " << t << " unit " << u;
      }
      Reverb::IrqWatch off;
      rv.tick(0, 0, ram.data(), true, true, off);
      if (side == 1) current = std::max(start, (current + 1) & 0x3FFFF);
    }
  }
}

namespace {

std::vector<u8> saved(Reverb& rv, std::vector<u8>& ram) {
  StateIO s;
  rv.do_state(s, ram.data());  // settles the owed values first
  return s.buffer();
}

}  // namespace

TEST(SpuReverb, QuietTicksAreUnseenTicksOfSilence) {
  // Reverb::quiet_ticks(n) is n calls of unseen_tick(0, 0, n-1-k): the first n-128 skipped, the
  // rest owed. Both are compared by the saved state (which computes the owed values: every
  // output history slot, position, the buffer address and the input history) and then by the
  // output of 100 heard ticks of noise. Before, heard ticks of noise fill both histories with
  // values the owed ones must replace, then 0 to 70 ticks of input 0 (from 39 on, the FIR input
  // of an owed tick is 0). The work area (kTestReverbRegs: reads 80h..380h halfwords past the
  // buffer address) lies above the capture buffers (halfwords 0..7FFh) at ESA 1000h and FE00h;
  // at ESA 100h the reads start inside them, so quiet_ticks declines and changes nothing. At ESA
  // FE00h the buffer address wraps from 3FFFFh to 3F800h every 800h address steps (1000h ticks):
  // 5000 ticks wrap it at least once.
  std::vector<u8> ram(512 * 1024);
  test::Lcg noise{77};
  for (u8& b : ram) b = static_cast<u8>(noise.next(256));
  auto input = [&] { return static_cast<s32>(noise.next(0x10000)) - 0x8000; };
  for (u16 esa : {0x1000, 0xFE00, 0x0100}) {
    for (u32 n : {1u, 2u, 39u, 127u, 128u, 129u, 130u, 200u, 255u, 256u, 700u, 5000u}) {
      for (u32 zeros : {0u, 5u, 38u, 70u}) {
        Reverb a;
        a.regs = test::kTestReverbRegs;
        a.write_base(esa);
        Reverb::IrqWatch none;
        for (u32 t = 0; t < 150 + n % 7; ++t) a.tick(input(), input(), ram.data(), false, true, none);
        for (u32 t = 0; t < zeros; ++t) a.owe_tick(0, 0, ram.data());
        Reverb b = a;
        const std::string what = "ESA " + std::to_string(esa) + " n " + std::to_string(n) + " zeros " + std::to_string(zeros);
        if (esa == 0x0100) {
          Reverb before = a;
          ASSERT_FALSE(a.quiet_ticks(n)) << what;
          ASSERT_EQ(saved(a, ram), saved(before, ram)) << what;
          continue;
        }
        ASSERT_TRUE(a.quiet_ticks(n)) << what;
        for (u32 k = 0; k < n; ++k) b.unseen_tick(0, 0, n - 1 - k, ram.data());
        ASSERT_EQ(saved(a, ram), saved(b, ram)) << what;
        for (u32 t = 0; t < 100; ++t) {
          const s32 l = t < 50 ? 0 : input(), r = t < 50 ? 0 : input();
          const StereoSample x = a.tick(l, r, ram.data(), false, true, none), y = b.tick(l, r, ram.data(), false, true, none);
          ASSERT_TRUE(x.left == y.left && x.right == y.right) << what << " tick " << t;
        }
      }
    }
  }
}

TEST(SpuReverb, QuietTicksDeclineWhereReadsReachTheCaptureBuffers) {
  // ESA 100h: the work area is halfwords 400h..3FFFFh, over the capture buffers (0..7FFh). After
  // 2 * 500h ticks the buffer address is 900h and kTestReverbRegs' reads (80h..380h past it) lie
  // above them; mLCOMB1 = mRCOMB1 = FD80h puts one read at 900h + 3F600h = 3FF00h, which moves
  // up a halfword every two ticks and wraps to 400h on tick 2 * 100h = 512. So 400 quiet ticks
  // may be made at once, 600 may not, and after 400 only 112 more, made or not.
  std::vector<u8> ram(512 * 1024, 0);
  Reverb rv;
  rv.regs = test::kTestReverbRegs;
  rv.write_base(0x0100);
  for (u32 t = 0; t < 2 * 0x500; ++t) rv.skip_tick(0, 0);
  rv.regs[Reverb::mLCOMB1] = rv.regs[Reverb::mRCOMB1] = 0xFD80;
  rv.settle(ram.data());  // as the SPU does when a register changes
  Reverb copy = rv;
  EXPECT_FALSE(copy.quiet_ticks(600));
  EXPECT_TRUE(rv.quiet_ticks(400));
  copy = rv;
  EXPECT_FALSE(copy.quiet_ticks(200));
  EXPECT_TRUE(rv.quiet_ticks(100));
}
