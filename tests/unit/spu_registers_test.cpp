// SPU register interface (psx-spx "SPU Bus-Width", "SPU Memory Access", "SPU Control and
// Status Register"): narrow and wide accesses, KON read-back, manual FIFO writes, DMA
// transfers, transfer IRQs, CD audio mixing and the capture buffers.
#include <gtest/gtest.h>

#include "spu_test_util.h"

using namespace psx;
using psx::test::SpuRig;

TEST(SpuRegisters, BusWidths) {
  SpuRig r;
  r.w16(0x1F801C04, 0x1234);  // voice 0 pitch
  EXPECT_EQ(r.spu.io_read(0x004, 1), 0x34u);
  EXPECT_EQ(r.spu.io_read(0x005, 1), 0x12u);
  r.spu.io_write(0x005, 0xFF, 1);  // odd 8-bit writes are ignored
  EXPECT_EQ(r.r16(0x1F801C04), 0x1234);
  r.spu.io_write(0x004, 0x5678, 1);  // even 8-bit writes act as 16-bit writes
  EXPECT_EQ(r.r16(0x1F801C04), 0x5678);
  r.spu.io_write(0x004, 0xAAAA0001, 4);  // pitch and SSA
  EXPECT_EQ(r.r16(0x1F801C04), 0x0001);
  EXPECT_EQ(r.r16(0x1F801C06), 0xAAAA);
  EXPECT_EQ(r.spu.io_read(0x004, 4), 0xAAAA0001u);
  // KON reads back the last written value; unknown registers behave as RAM.
  r.w16(0x1F801D88, 0x0000);
  r.w16(0x1F801DA0, 0xBEEF);
  EXPECT_EQ(r.r16(0x1F801DA0), 0xBEEF);
  r.w16(0x1F801E60, 0x1357);
  EXPECT_EQ(r.r16(0x1F801E60), 0x1357);
  // Voice 0 cannot be pitch-modulated (PMON bit 0 unused).
  r.w16(0x1F801D90, 0xFFFF);
  EXPECT_EQ(r.r16(0x1F801D90), 0xFFFE);
}

TEST(SpuRegisters, ManualWriteThroughTheFifo) {
  SpuRig r;
  r.w16(0x1F801DAC, 0x0004);
  r.w16(0x1F801DAA, 0xC000);  // transfer mode: stop
  r.w16(0x1F801DA6, 0x1000 / 8);
  for (u16 v : {0x1111, 0x2222, 0x3333}) r.w16(0x1F801DA8, v);
  EXPECT_EQ(r.spu.ram()[0x1000], 0);  // still in the FIFO
  r.w16(0x1F801DAA, 0xC010);          // manual write
  EXPECT_EQ(r.r16(0x1F801DAE) & 0x3F, 0x10);
  EXPECT_EQ(r.spu.ram()[0x1000], 0x11);
  EXPECT_EQ(r.spu.ram()[0x1005], 0x33);
  r.w16(0x1F801DA8, 0x4444);  // already in manual mode: lands at once
  EXPECT_EQ(r.spu.ram()[0x1006], 0x44);
  EXPECT_EQ(r.r16(0x1F801DA6), 0x1000 / 8);  // TSA itself does not move
}

TEST(SpuRegisters, DmaWriteReadAndTransferIrq) {
  SpuRig r;
  r.w16(0x1F801DA6, 0x2000 / 8);
  r.w16(0x1F801DAA, 0xC020);  // DMA write
  EXPECT_TRUE(r.spu.dma_request());
  EXPECT_EQ(r.r16(0x1F801DAE) & 0x3A0, 0x1A0);  // mode 20h, bit 7, DMA write request (bit 8)
  const u32 words[2] = {0x44332211, 0x88776655};
  r.spu.dma_write(words, 2);
  EXPECT_EQ(r.spu.ram()[0x2000], 0x11);
  EXPECT_EQ(r.spu.ram()[0x2007], 0x88);
  r.w16(0x1F801DA6, 0x2000 / 8);
  r.w16(0x1F801DAA, 0xC030);  // DMA read
  EXPECT_EQ(r.r16(0x1F801DAE) & 0x300, 0x200);
  u32 back[2] = {};
  r.spu.dma_read(back, 2);
  EXPECT_EQ(back[0], words[0]);
  EXPECT_EQ(back[1], words[1]);
  r.w16(0x1F801DAA, 0xC000);
  EXPECT_FALSE(r.spu.dma_request());

  // A transfer touching the IRQ address raises IRQ9 (once, until acknowledged).
  r.w16(0x1F801DA4, 0x2008 / 8);
  r.w16(0x1F801DA6, 0x2000 / 8);
  r.w16(0x1F801DAA, 0xC060);
  r.spu.dma_write(words, 2);
  EXPECT_EQ(r.irq.stat() & (1u << 9), 0u);
  r.spu.dma_write(words, 1);
  EXPECT_EQ(r.irq.stat() & (1u << 9), 1u << 9);
  EXPECT_EQ(r.r16(0x1F801DAE) & 0x40, 0x40);
}

TEST(SpuRegisters, CdAudioVolumesAndCaptureBuffers) {
  SpuRig r;
  r.cd.push({1000, -2000});
  r.cd.push({3000, 4000});
  r.w16(0x1F801DAA, 0x0001);  // CD input on; the SPU itself disabled (CD does not care)
  r.w16(0x1F801DB0, 0x4000);  // AVOLL 0.5
  r.w16(0x1F801DB2, 0x2000);  // AVOLR 0.25
  r.w16(0x1F801D80, 0x3FFF);  // main 7FFEh
  r.w16(0x1F801D82, 0x3FFF);
  r.run_samples(3);
  auto out = r.take();
  ASSERT_EQ(out.size(), 3u);
  // The fixed main volume is latched on the first sample, so sample 0 is at volume 0.
  EXPECT_EQ(out[0].left, 0);
  // 3000*0.5 = 1500, then * 7FFEh >> 15 = 1499; 4000*0.25 = 1000 -> 999.
  EXPECT_EQ(out[1].left, 1499);
  EXPECT_EQ(out[1].right, 999);
  EXPECT_EQ(out[2].left, 0);  // FIFO empty: silence
  // The capture buffers hold the CD samples before volume, one halfword per sample.
  auto h = [&](u32 a) { return static_cast<s16>(r.spu.ram()[a] | r.spu.ram()[a + 1] << 8); };
  EXPECT_EQ(h(0x000), 1000);
  EXPECT_EQ(h(0x400), -2000);
  EXPECT_EQ(h(0x002), 3000);
  EXPECT_EQ(h(0x402), 4000);
  r.run_samples(0x100 - 3);
  EXPECT_EQ(r.r16(0x1F801DAE) & 0x800, 0x800);  // writing the second half now
}

TEST(SpuRegisters, OutputLimitDropsTheOlderHalf) {
  SpuRig r;
  r.spu.set_output_limit(100);
  r.run_samples(100);
  EXPECT_EQ(r.spu.pending_samples(), 100u);
  r.run_samples(1);  // 100 reached: the older 50 go, the new one is appended
  EXPECT_EQ(r.spu.pending_samples(), 51u);
}
