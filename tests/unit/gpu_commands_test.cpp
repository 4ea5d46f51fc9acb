// GP0 VRAM commands (fill, copy, CPU<->VRAM transfers), GP1 display control, GPUSTAT bits, GPU
// info queries, interrupts, video timing, display output and save states (psx-spx "GPU").
#include <algorithm>
#include <cstring>
#include <vector>

#include "gpu_test_util.h"

namespace psx::test {
namespace {

TEST_F(GpuTest, ResetStatus) {
  // psx-spx: GPUSTAT after GP1(00) is 14802000h (display off, ready flags, field bit 13);
  // bit 31 depends on the line being displayed.
  EXPECT_EQ(stat() & 0x7FFFFFFF, 0x14802000u);
}

TEST_F(GpuTest, FillRoundsXAndWidthTo16AndIgnoresAreaAndMask) {
  poke(16, 0, 0x8000);  // a masked pixel
  gp0({0xE6000002, 0xE3000000 | 200, 0xE4000000 | (10 << 10) | 300});
  // x 0x13 -> 0x10 (rounded down), width 0x11 -> 0x20 (rounded up): pixels 16..47.
  gp0({0x020000F8, 0x00000013, 0x00020011});
  EXPECT_EQ(px(15, 0), 0);
  EXPECT_EQ(px(16, 0), 0x001F);  // the mask bit did not protect it; bit 15 written as 0
  EXPECT_EQ(px(47, 1), 0x001F);
  EXPECT_EQ(px(48, 0), 0);
  EXPECT_EQ(px(16, 2), 0);
}

TEST_F(GpuTest, FillWrapsAtVramEdges) {
  // x = 1008, width 32 -> 1008..1023 then 0..15; y = 511, height 2 -> rows 511 and 0.
  gp0({0x0200F800, (511u << 16) | 1008, 0x00020020});
  EXPECT_EQ(px(1023, 511), 0x03E0);
  EXPECT_EQ(px(15, 0), 0x03E0);
  EXPECT_EQ(px(16, 0), 0);
  EXPECT_EQ(px(1007, 511), 0);
}

TEST_F(GpuTest, CpuToVramOddSizeAndWrap) {
  // 3x1 at x = 1022: pixels land at 1022, 1023, then wrap to 0; the 4th halfword is dropped and
  // the next word is a new command.
  gp0({0xA0000000, 0x000A03FE, 0x00010003, 0x22221111, 0x44443333});
  EXPECT_EQ(px(1022, 10), 0x1111);
  EXPECT_EQ(px(1023, 10), 0x2222);
  EXPECT_EQ(px(0, 10), 0x3333);
  EXPECT_EQ(px(1, 10), 0);
  gp0({0x680000F8, xy(5, 5)});
  EXPECT_EQ(px(5, 5), 0x001F);
}

TEST_F(GpuTest, CpuToVramHonoursMaskSettings) {
  poke(0, 20, 0x8001);
  gp0({0xE6000003});  // set and check
  gp0({0xA0000000, 0x00140000, 0x00010002, 0x00050004});
  EXPECT_EQ(px(0, 20), 0x8001);  // protected
  EXPECT_EQ(px(1, 20), 0x8005);  // written with bit 15 forced
}

TEST_F(GpuTest, VramToCpuReadsPairsAndSetsReadyFlag) {
  gp0({0xA0000000, 0x00300100, 0x00020002, 0x22221111, 0x44443333});
  EXPECT_EQ(stat() & (1u << 27), 0u);
  gp0({0xC0000000, 0x00300100, 0x00020003});  // 3x2 = 6 pixels = 3 words
  EXPECT_NE(stat() & (1u << 27), 0u);
  EXPECT_EQ(gpu.io_read(0, 4), 0x22221111u);
  EXPECT_EQ(gpu.io_read(0, 4), 0x33330000u);  // (258,48) = 0, then the next row's (256,49)
  EXPECT_EQ(gpu.io_read(0, 4), 0x00004444u);  // (257,49), (258,49) = 0
  EXPECT_EQ(stat() & (1u << 27), 0u);
}

TEST_F(GpuTest, VramToVramCopy) {
  gp0({0xA0000000, 0x00000000, 0x00010004, 0x00020001, 0x00040003});
  gp0({0x80000000, 0x00000000, 0x00050000, 0x00010004});  // copy 4x1 from (0,0) to (0,5)
  for (u32 i = 0; i < 4; ++i) EXPECT_EQ(px(i, 5), i + 1);
  // Overlapping copy one pixel right within the row: reads the row before writing.
  gp0({0x80000000, 0x00000000, 0x00000001, 0x00010004});
  EXPECT_EQ(px(0, 0), 1);
  for (u32 i = 0; i < 4; ++i) EXPECT_EQ(px(1 + i, 0), i + 1);
  // Size 0 means the maximum: a 0x0 copy would be 1024x512 (here we only check it runs
  // without touching anything outside VRAM by copying VRAM onto itself).
  gp0({0x80000000, 0, 0, 0});
  EXPECT_EQ(px(4, 0), 4);
}

TEST_F(GpuTest, CopyChecksAndSetsMask) {
  poke(0, 30, 0x0007);
  poke(5, 30, 0x8000);
  gp0({0xE6000003});
  gp0({0x80000000, 0x001E0000, 0x001E0004, 0x00010001});  // (0,30) -> (4,30)
  gp0({0x80000000, 0x001E0000, 0x001E0005, 0x00010001});  // (0,30) -> (5,30): protected
  EXPECT_EQ(px(4, 30), 0x8007);
  EXPECT_EQ(px(5, 30), 0x8000);
}

TEST_F(GpuTest, GpuInfoQueries) {
  gp0({0xE2012345, 0xE3012345, 0xE4054321, 0xE5123456});
  gp1(0x10000002);
  EXPECT_EQ(gpu.io_read(0, 4), 0x12345u);
  gp1(0x10000003);
  EXPECT_EQ(gpu.io_read(0, 4), 0x12345u & 0x7FFFF);
  gp1(0x10000004);
  EXPECT_EQ(gpu.io_read(0, 4), 0x54321u & 0x7FFFF);
  gp1(0x10000005);
  EXPECT_EQ(gpu.io_read(0, 4), 0x123456u & 0x3FFFFF);
  gp1(0x10000007);
  EXPECT_EQ(gpu.io_read(0, 4), 2u);
  gp1(0x10000000);  // no answer: GPUREAD keeps the last one
  EXPECT_EQ(gpu.io_read(0, 4), 2u);
}

TEST_F(GpuTest, StatusReflectsDrawModeDisplayModeAndDma) {
  gp0({0xE100060F});   // page X 15, dither (bit 9), draw to display (bit 10)
  gp0({0xE6000003});   // mask bits -> 11, 12
  gp1(0x0800003F);     // 640 wide, 480 lines, PAL, 24-bit, interlace
  gp1(0x03000000);     // display on
  u32 s = stat();
  EXPECT_EQ(s & 0x7FF, 0x60Fu);
  EXPECT_EQ((s >> 11) & 3, 3u);
  EXPECT_EQ((s >> 17) & 0x3F, 0x3Fu);
  EXPECT_EQ((s >> 23) & 1, 0u);
  gp1(0x08000040);  // 368 mode -> bit 16
  EXPECT_EQ((stat() >> 16) & 1, 1u);
  // DMA request (bit 25) per direction: 0 -> 0, 1 -> 1, 2 -> bit 28, 3 -> bit 27.
  gp1(0x04000000);
  EXPECT_EQ((stat() >> 25) & 1, 0u);
  EXPECT_FALSE(gpu.dma_request());
  gp1(0x04000001);
  EXPECT_EQ((stat() >> 25) & 1, 1u);
  gp1(0x04000002);
  EXPECT_EQ((stat() >> 25) & 1, (stat() >> 28) & 1);
  EXPECT_EQ((stat() >> 29) & 3, 2u);
  gp1(0x04000003);
  EXPECT_EQ((stat() >> 25) & 1, 0u);  // nothing to send
  gp0({0xC0000000, 0, 0x00010001});
  EXPECT_EQ((stat() >> 25) & 1, 1u);
  EXPECT_TRUE(gpu.dma_request());
}

// GP0(C0) leaves the command FIFO empty: bit 28 stays set (a program's DrawSync waits for it
// after the command: ps1-tests gpu/bandwidth, which passes on a console), 27 and the DMA
// request in direction 3 until the last word is read, 26 clear until then.
TEST_F(GpuTest, VramToCpuTransferLeavesTheFifoReady) {
  constexpr u32 kRequest = 1u << 25, kCmd = 1u << 26, kVram = 1u << 27, kBlock = 1u << 28;
  gp1(0x04000003);
  gp0({0xC0000000, 0, 0x00010004});  // 4x1 pixels: two words
  EXPECT_EQ(stat() & (kRequest | kCmd | kVram | kBlock), kRequest | kVram | kBlock);
  gpu.io_read(0, 4), gpu.io_read(0, 4);
  EXPECT_EQ(stat() & (kRequest | kCmd | kVram | kBlock), kCmd | kBlock);
  gp1(0x04000002);
  gp0({0xC0000000, 0, 0x00010002});
  EXPECT_EQ(stat() & (kRequest | kBlock), kRequest | kBlock);
  EXPECT_TRUE(gpu.dma_request());
}

TEST_F(GpuTest, Irq1SetAndAcknowledge) {
  gp0({0x1F000000});
  EXPECT_NE(stat() & (1u << 24), 0u);
  EXPECT_NE(irq.stat() & (1u << static_cast<u32>(Irq::Gpu)), 0u);
  gp1(0x02000000);
  EXPECT_EQ(stat() & (1u << 24), 0u);
}

TEST_F(GpuTest, DmaWriteCarriesCommandsAndTransfers) {
  const u32 words[] = {0xA0000000, 0x00400000, 0x00010003, 0x00020001, 0x00000003, 0x680000F8, 0x00410000};
  gpu.dma_write(words, 7);
  EXPECT_EQ(px(0, 64), 1);
  EXPECT_EQ(px(2, 64), 3);
  EXPECT_EQ(px(0, 65), 0x001F);
  u32 back[2] = {};
  gp0({0xC0000000, 0x00400000, 0x00010003});
  gpu.dma_read(back, 2);
  EXPECT_EQ(back[0], 0x00020001u);
  EXPECT_EQ(back[1], 0x00000003u);
}

// DMA channel 2 hands GP0 the same words a program would write to the port (psx-spx "GPU
// Render/Transfer Commands" via DMA): a stream of every kind of command, cut into DMA blocks at
// every offset pattern (whole commands, commands split across blocks, single words), leaves the
// GPU in the same state, VRAM included, as the words written one by one.
TEST(GpuDma, BlocksCarryTheSameCommandsAsPortWrites) {
  const std::vector<u32> stream = {
      0xE1000208, 0xE3000000, 0xE4000000 | 511u << 10 | 1023, 0xE5000000, 0xE6000000,
      0x02102030, 0x00100010, 0x00200040,                                   // fill
      0x20FF0000, 0x00100010, 0x00100060, 0x00500020,                       // flat triangle
      0x38102030, 0x00000000, 0x00405060, 0x00000140, 0x00708090, 0x00F00000, 0x00A0B0C0, 0x00F00140,  // shaded quad
      0x2C808080, 0x00300030, 0x78000000, 0x00300050, 0x00080010, 0x00500030, 0x00001000, 0x00500050, 0x00001010,
      0x40FFFFFF, 0x00050005, 0x00600090,                                   // line
      0x58FF0000, 0x00100100, 0x0000FF00, 0x00200180, 0x000000FF, 0x00900120, 0x55555555,  // shaded polyline
      0x64808080, 0x00700070, 0x78000000, 0x00100020,                       // textured rectangle
      0x7C804020, 0x00900090, 0x78000404,                                   // 16x16 sprite
      0xA0000000, 0x01000200, 0x00020003, 0x7FFF001F, 0x03E07C00, 0x12345678,  // CPU to VRAM, 3x2
      0x80000000, 0x00000000, 0x01800300, 0x00200020,                       // VRAM to VRAM
      0x1F000000, 0x00000000,                                               // IRQ, NOP
  };
  for (u32 pattern = 0; pattern < 8; ++pattern) {
    SCOPED_TRACE(pattern);
    Scheduler port_sched, dma_sched;
    InterruptController port_irq, dma_irq;
    Gpu port(port_sched, port_irq), dma(dma_sched, dma_irq);
    for (u32 w : stream) port.io_write(0, w, 4);
    // Block sizes 1..8 words, from a pattern that differs per run.
    for (size_t i = 0, k = 0; i < stream.size(); ++k) {
      const u32 n = std::min<u32>(1 + (pattern * 5 + k * 3) % 8, static_cast<u32>(stream.size() - i));
      dma.dma_write(stream.data() + i, n);
      i += n;
    }
    StateIO a, b;
    port.do_state(a), dma.do_state(b);
    EXPECT_EQ(a.buffer(), b.buffer());
    EXPECT_EQ(std::memcmp(port.vram(), dma.vram(), gpu::kVramPixels * 2), 0);
  }
}

}  // namespace
}  // namespace psx::test
