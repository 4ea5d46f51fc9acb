// GPUSTAT while the GPU draws (issue 59 item 8), as ps1-tests gpu/gpustat's cases pass on a
// console (its psx.log; the whole program's cases are tests/roms/gpu_timing.c's): bit 26
// (ready for a command word) reads 0 for as long as the drawing takes; bit 28 (ready for a DMA
// block, and 25 in DMA direction 2) only while a second command waits behind the one drawing.
// The times come from ps1-tests gpu/bandwidth's console log: 400 full-screen (320x240) commands
// took 1216 HBlanks (fills), 7603 (rectangles) and 7727 (quads) of 2152.87 CPU cycles (3413
// video clocks at 53.693175 MHz), 399 of them drawn when the counter is read: per command
// 1216 * 2152.87 / 399 = 6,561 CPU cycles, 41,023 and 41,692.
#include "gpu_test_util.h"

namespace psx::test {
namespace {

constexpr u32 kDmaRequest = 1u << 25, kReadyCmd = 1u << 26, kReadyDma = 1u << 28;

class GpuBusyTest : public GpuTest {
 protected:
  // The command keeps the GPU busy until `done` cycles (within 2%) after it was written.
  void expect_busy_for(Cycles done) {
    EXPECT_EQ(stat() & (kReadyCmd | kReadyDma), kReadyDma) << "right after the command";
    run(done * 98 / 100);
    EXPECT_EQ(stat() & (kReadyCmd | kReadyDma), kReadyDma) << "at 98% of " << done;
    run(done * 4 / 100);
    EXPECT_EQ(stat() & (kReadyCmd | kReadyDma), kReadyCmd | kReadyDma) << "at 102% of " << done;
  }
};

TEST_F(GpuBusyTest, ReadyBitsBeforeAnyDrawing) {
  EXPECT_EQ(stat() & (kReadyCmd | kReadyDma), kReadyCmd | kReadyDma);
}

TEST_F(GpuBusyTest, FullScreenFillTakesItsMeasuredTime) {
  gp0({0x02000000, xy(0, 0), xy(320, 240)});
  expect_busy_for(6561);
}

TEST_F(GpuBusyTest, FullScreenRectangleTakesItsMeasuredTime) {
  gp0({0x60000000, xy(0, 0), xy(320, 240)});
  expect_busy_for(41023);
}

TEST_F(GpuBusyTest, FullScreenQuadTakesItsMeasuredTime) {
  gp0({0x28000000, xy(0, 0), xy(320, 0), xy(0, 240), xy(320, 240)});
  expect_busy_for(41692);
}

// gpu/gpustat's linked-list case: the second rectangle waits in the FIFO while the first draws,
// so 28 and 25 (direction 2) read 0 too, until the second starts; 26 until it ends.
TEST_F(GpuBusyTest, ACommandWaitingBehindTheDrawingOneFillsTheFifo) {
  gp1(0x04000002);
  EXPECT_EQ(stat() & (kDmaRequest | kReadyCmd | kReadyDma), kDmaRequest | kReadyCmd | kReadyDma);
  gp0({0x60000000, xy(0, 0), xy(320, 240)});
  gp0({0x60000000, xy(0, 0), xy(320, 240)});  // starts when the first ends, at 41,023
  EXPECT_EQ(stat() & (kDmaRequest | kReadyCmd | kReadyDma), 0u);
  run(40200);
  EXPECT_EQ(stat() & (kDmaRequest | kReadyCmd | kReadyDma), 0u);
  run(1600);
  EXPECT_EQ(stat() & (kDmaRequest | kReadyCmd | kReadyDma), kDmaRequest | kReadyDma);
  run(41023);  // both: 82,046
  EXPECT_EQ(stat() & (kDmaRequest | kReadyCmd | kReadyDma), kDmaRequest | kReadyCmd | kReadyDma);
}

// psx-spx "Ready Bits": bit 26 is cleared while the GPU wants more parameters or data, so it reads
// 0 from a command's first word until its last (a rectangle outside the drawing area, which takes
// no drawing time), and through a polyline until its terminator (each read once its segments'
// drawing time, a few cycles, has passed).
TEST_F(GpuBusyTest, Bit26ReadsZeroWhileACommandsParametersArrive) {
  gp0({0xE3000000, 0xE4000000 | (99u << 10) | 99u});  // drawing area 0..99 x 0..99
  gp0({0x60000000});
  EXPECT_EQ(stat() & kReadyCmd, 0u) << "after the command word";
  gp0({xy(200, 200)});
  EXPECT_EQ(stat() & kReadyCmd, 0u) << "after the position";
  gp0({xy(10, 10)});
  EXPECT_EQ(stat() & kReadyCmd, kReadyCmd) << "after the size";
  gp0({0x48000000, xy(200, 200), xy(210, 200)});
  run(100);
  EXPECT_EQ(stat() & kReadyCmd, 0u) << "a polyline after its first segment";
  gp0({xy(220, 200)});
  run(100);
  EXPECT_EQ(stat() & kReadyCmd, 0u) << "a polyline's next vertex";
  gp0({0x55555555});
  EXPECT_EQ(stat() & kReadyCmd, kReadyCmd) << "after the terminator";
}

TEST_F(GpuBusyTest, DrawingOutsideTheDrawingAreaTakesNoTime) {
  gp0({0xE3000000, 0xE4000000 | (99u << 10) | 99u});  // drawing area 0..99 x 0..99
  gp0({0x60000000, xy(200, 200), xy(100, 100)});
  EXPECT_EQ(stat() & (kReadyCmd | kReadyDma), kReadyCmd | kReadyDma);
}

}  // namespace
}  // namespace psx::test
