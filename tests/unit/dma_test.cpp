// DMA controller tests: register rules and transfer results from psx-spx "DMA Channels".
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/bus.h"
#include "core/dma.h"
#include "core/endian.h"
#include "core/irq.h"
#include "core/scheduler.h"

namespace psx {
namespace {

// A device side that records what it receives and hands out a counting sequence.
struct FakePort : DmaPort {
  std::vector<u32> received;
  u32 next_out = 0x100;
  bool request = true;
  u32 busy_word = 0;  // a word after which the device stops requesting (as the GPU after GP0(C0))
  std::vector<int>* order = nullptr;  // shared log of which port moved words, in order
  int id = 0;
  void dma_write(const u32* w, u32 n) override {
    received.insert(received.end(), w, w + n);
    if (busy_word != 0 && std::find(w, w + n, busy_word) != w + n) request = false;
    if (order) order->push_back(id);
  }
  void dma_read(u32* w, u32 n) override {
    for (u32 i = 0; i < n; ++i) w[i] = next_out++;
    if (order) order->push_back(id);
  }
  bool dma_request() const override { return request; }
  Cycles block_cycles_per_word = 0;  // the device's own time per word of a block (SPU FIFO)
  Cycles dma_block_cycles(u32 words) const override { return block_cycles_per_word * words; }
};

constexpr u32 reg(u32 ch, u32 r) { return ch * 0x10 + r; }
constexpr u32 kMadr = 0, kBcr = 4, kChcr = 8, kDpcr = 0x70, kDicr = 0x74;

class DmaTest : public ::testing::Test {
 protected:
  Scheduler sched;
  InterruptController irq;
  Bus bus{sched, irq};
  Dma dma{sched, irq, bus};
  FakePort gpu, spu, cdrom, mdec_in, mdec_out;

  void SetUp() override {
    dma.connect(Dma::MdecIn, &mdec_in);
    dma.connect(Dma::MdecOut, &mdec_out);
    dma.connect(Dma::Gpu, &gpu);
    dma.connect(Dma::Cdrom, &cdrom);
    dma.connect(Dma::Spu, &spu);
    irq.write(4, 0x7FF);  // unmask everything so stat() shows raised lines
  }
  u32 ram32(u32 addr) { return psx::load_le32(bus.ram() + addr); }
  void set_ram32(u32 addr, u32 v) { psx::store_le32(bus.ram() + addr, v); }
  void w(u32 off, u32 v) { dma.io_write(off, v, 4); }
  u32 r(u32 off) { return dma.io_read(off, 4); }
  bool dma_irq() { return irq.stat() & (1u << static_cast<u32>(Irq::Dma)); }
  // Lets scheduled DMA work (polls, chopping windows) run for `cycles`.
  void run_for(Cycles cycles) {
    Cycles end = sched.now() + cycles;
    while (sched.now() < end) {
      sched.advance(1);
      sched.run_due_events();
    }
  }
};

TEST_F(DmaTest, DpcrResetValueAndOtcChcrFixedBits) {
  EXPECT_EQ(r(kDpcr), 0x07654321u);  // psx-spx: initial value on reset
  // D6_CHCR: only bits 24, 28, 30 writable; bit 1 always 1.
  w(reg(6, kChcr), 0xAE7F0F01);
  EXPECT_EQ(r(reg(6, kChcr)), 0x00000002u);
  // MADR keeps 24 bits.
  w(reg(2, kMadr), 0xFF123457);
  EXPECT_EQ(r(reg(2, kMadr)), 0x00123457u);
}

TEST_F(DmaTest, OtcBuildsReversedList) {
  w(kDpcr, 0x08000000);  // enable DMA6 only
  w(kDicr, 0x00C00000);  // master enable + DMA6 IRQ enable
  w(reg(6, kMadr), 0x001000);
  w(reg(6, kBcr), 4);
  Cycles t0 = sched.now();
  w(reg(6, kChcr), 0x11000002);
  // Entry at A points to A-4; the last (lowest) holds the end code 0x00FFFFFF.
  EXPECT_EQ(ram32(0x1000), 0x000FFCu);
  EXPECT_EQ(ram32(0x0FFC), 0x000FF8u);
  EXPECT_EQ(ram32(0x0FF8), 0x000FF4u);
  EXPECT_EQ(ram32(0x0FF4), 0x00FFFFFFu);
  EXPECT_EQ(ram32(0x0FF0), 0u);  // nothing below
  EXPECT_EQ(ram32(0x1004), 0u);  // nothing above
  EXPECT_EQ(r(reg(6, kChcr)), 0x00000002u);  // busy and trigger cleared
  EXPECT_EQ(r(reg(6, kMadr)), 0x001000u);    // sync mode 0 leaves MADR
  // 4 words at 0x110 clocks per 0x100 words = 4.25 clocks -> 4 whole cycles charged so far.
  EXPECT_EQ(sched.now() - t0, 4u);
  EXPECT_EQ(r(kDicr), 0x80C00000u | (1u << 30));
  EXPECT_TRUE(dma_irq());
}

TEST_F(DmaTest, OtcWithoutTriggerNeverStarts) {
  // ps1-tests dma/otc-test (testOtcWontStartOnAutomaticMode, passed by the console): CHCR
  // 01000002h leaves the word in RAM as it was.
  w(kDpcr, 0x08000000);
  set_ram32(0x2000, 0x11111111);
  w(reg(6, kMadr), 0x2000);
  w(reg(6, kBcr), 1);
  w(reg(6, kChcr), 0x01000002);
  run_for(1000);
  EXPECT_EQ(ram32(0x2000), 0x11111111u);
}

TEST_F(DmaTest, DisabledChannelWaitsForDpcr) {
  w(kDpcr, 0);
  w(reg(6, kMadr), 0x2000);
  w(reg(6, kBcr), 2);
  w(reg(6, kChcr), 0x11000002);
  EXPECT_EQ(ram32(0x2000), 0u);
  EXPECT_EQ(r(reg(6, kChcr)) & Dma::kChcrBusy, Dma::kChcrBusy);
  w(kDpcr, 0x08000000);
  EXPECT_EQ(ram32(0x2000), 0x1FFCu);
  EXPECT_EQ(ram32(0x1FFC), 0x00FFFFFFu);
}

TEST_F(DmaTest, DicrFlagOnlyWhenChannelEnabledAndMasterFlagRules) {
  w(kDpcr, 0x08000000);
  w(kDicr, 0x00800000);  // master enable, but DMA6 IRQ not enabled
  w(reg(6, kMadr), 0x100);
  w(reg(6, kBcr), 1);
  w(reg(6, kChcr), 0x11000002);
  EXPECT_EQ(r(kDicr), 0x00800000u);  // flag not set: bit 22 was 0
  EXPECT_FALSE(dma_irq());

  // Flag set while enabled, but master enable off: bit 31 stays 0.
  w(kDicr, 0x00400000);
  w(reg(6, kChcr), 0x11000002);
  EXPECT_EQ(r(kDicr), 0x40400000u);
  EXPECT_FALSE(dma_irq());
  // Setting master enable now makes bit 31 rise: IRQ3.
  w(kDicr, 0x00C00000);
  EXPECT_EQ(r(kDicr), 0xC0C00000u);
  EXPECT_TRUE(dma_irq());

  // Writing 0 to a flag keeps it; writing 1 acknowledges it.
  irq.write(0, 0);
  w(kDicr, 0x00C00000);
  EXPECT_EQ(r(kDicr) & 0x40000000u, 0x40000000u);
  w(kDicr, 0x40C00000);
  EXPECT_EQ(r(kDicr), 0x00C00000u);
  EXPECT_FALSE(dma_irq());
}

TEST_F(DmaTest, ForceIrqRaisesOnRisingEdgeOnly) {
  w(kDicr, 0x00008000);
  EXPECT_EQ(r(kDicr), 0x80008000u);
  EXPECT_TRUE(dma_irq());
  irq.write(0, 0);
  w(kDicr, 0x00008000);  // bit 31 already 1: no new edge
  EXPECT_FALSE(dma_irq());
  w(kDicr, 0);
  EXPECT_EQ(r(kDicr), 0u);
  w(kDicr, 0x00008000);
  EXPECT_TRUE(dma_irq());
  // Bits 0-5 are read/write, 6-14 always zero.
  w(kDicr, 0x00007FFF);
  EXPECT_EQ(r(kDicr), 0x0000003Fu);
}

TEST_F(DmaTest, DicrMasterFlagIgnoresChannelEnablesAndRisesOnEdges) {
  // psx-spx DICR: bit 31 = bit 15 OR (bit 23 AND any flag 24-30); the enables 16-22 only decide
  // whether a finishing channel sets its flag; I_STAT bit 3 fires on bit 31's 0-to-1 edge.
  w(kDpcr, 0x00000800);  // DMA2 enable
  w(kDicr, 0x00840000);  // master enable + DMA2 enable
  w(reg(2, kMadr), 0x100);
  w(reg(2, kBcr), 1);
  w(reg(2, kChcr), 0x11000001);  // from RAM, burst, start+trigger
  EXPECT_EQ(r(kDicr), 0x84840000u);
  EXPECT_TRUE(dma_irq());
  irq.write(0, 0);
  w(kDicr, 0x00800000);  // DMA2 enable cleared: its pending flag still holds bit 31
  EXPECT_EQ(r(kDicr), 0x84800000u);
  EXPECT_FALSE(dma_irq());  // bit 31 stayed 1: no edge
  w(kDicr, 0);
  EXPECT_EQ(r(kDicr), 0x04000000u);
  EXPECT_FALSE(dma_irq());
  w(kDicr, 0x00800000);  // master enable again, every channel enable clear: a new edge
  EXPECT_EQ(r(kDicr), 0x84800000u);
  EXPECT_TRUE(dma_irq());
  irq.write(0, 0);
  w(kDicr, 0x04800000);  // writing 1 to the flag clears it, and bit 31 with it
  EXPECT_EQ(r(kDicr), 0x00800000u);
  EXPECT_FALSE(dma_irq());
  // Force IRQ (bit 15) is stored, reads back and forces bit 31 even with bit 23 clear.
  w(kDicr, 0x00008000);
  EXPECT_EQ(r(kDicr), 0x80008000u);
  EXPECT_TRUE(dma_irq());
}

TEST_F(DmaTest, BurstToDeviceKeepsRegistersAndChargesRate) {
  w(kDpcr, 0x00008000);  // DMA3 enable
  for (u32 i = 0; i < 8; ++i) set_ram32(0x400 + 4 * i, 0xA0 + i);
  w(reg(3, kMadr), 0x400);
  w(reg(3, kBcr), 0x00010008);
  Cycles t0 = sched.now();
  w(reg(3, kChcr), 0x11000001);  // from RAM, burst, start+trigger
  ASSERT_EQ(cdrom.received.size(), 8u);
  for (u32 i = 0; i < 8; ++i) EXPECT_EQ(cdrom.received[i], 0xA0 + i);
  EXPECT_EQ(r(reg(3, kMadr)), 0x400u);
  EXPECT_EQ(r(reg(3, kBcr)), 0x00010008u);
  EXPECT_EQ(r(reg(3, kChcr)), 0x00000001u);
  EXPECT_EQ(sched.now() - t0, 8u * 24);  // CD-ROM: 24 clocks per word (BIOS default)
}

TEST_F(DmaTest, CdromRateFollowsDelayRegister) {
  // psx-spx "DMA Transfer Rates": CDROM/GAMES 40 clks/word (2800h per 100h words), with the
  // CDROM Delay/Size setting 0x00020943 games use.
  bus.write32(0x1F801018, 0x00020943);
  w(kDpcr, 0x00008000);
  w(reg(3, kMadr), 0x400);
  w(reg(3, kBcr), 0x00010100);
  Cycles t0 = sched.now();
  w(reg(3, kChcr), 0x11000001);
  EXPECT_EQ(sched.now() - t0, 0x2800u);
}

TEST_F(DmaTest, BurstFromDeviceBackward) {
  w(kDpcr, 0x00008000);
  w(reg(3, kMadr), 0x80C);
  w(reg(3, kBcr), 3);
  w(reg(3, kChcr), 0x11000002);  // to RAM, step -4
  EXPECT_EQ(ram32(0x80C), 0x100u);
  EXPECT_EQ(ram32(0x808), 0x101u);
  EXPECT_EQ(ram32(0x804), 0x102u);
  EXPECT_EQ(ram32(0x800), 0u);
}

TEST_F(DmaTest, BurstChoppingGivesCpuWindows) {
  w(kDpcr, 0x00008000);
  w(reg(3, kMadr), 0x1000);
  w(reg(3, kBcr), 10);
  // Chopping: DMA window 1<<2 = 4 words (bits 16-18), CPU window 1<<5 = 32 clocks (bits 20-22).
  w(reg(3, kChcr), 0x11520100);
  EXPECT_EQ(cdrom.next_out, 0x104u);  // first window only
  EXPECT_EQ(r(reg(3, kMadr)), 0x1010u);
  EXPECT_EQ(r(reg(3, kBcr)), 6u);
  EXPECT_NE(r(reg(3, kChcr)) & Dma::kChcrBusy, 0u);
  // The CPU window, then 6 clocks more before the next DMA window (fitted to ps1-tests
  // dma/chopping: a window pair takes its words, its clocks and 6 more on the console).
  run_for(32 + 5);
  EXPECT_EQ(cdrom.next_out, 0x104u);  // CPU window not over
  run_for(1);
  EXPECT_EQ(cdrom.next_out, 0x108u);
  run_for(32 + 6 + 4 * 24);
  EXPECT_EQ(cdrom.next_out, 0x10Au);  // 10 words in all
  EXPECT_EQ(r(reg(3, kBcr)), 0u);
  EXPECT_EQ(r(reg(3, kMadr)), 0x1028u);
  EXPECT_EQ(r(reg(3, kChcr)) & Dma::kChcrBusy, 0u);
  for (u32 i = 0; i < 10; ++i) EXPECT_EQ(ram32(0x1000 + 4 * i), 0x100 + i);
}

TEST_F(DmaTest, SyncMode1BlocksFollowRequests) {
  w(kDpcr, 0x00080000);  // DMA4 (SPU)
  w(kDicr, 0x00900000);  // master + DMA4 enable
  for (u32 i = 0; i < 12; ++i) set_ram32(0x3000 + 4 * i, i + 1);
  spu.request = false;
  w(reg(4, kMadr), 0x3000);
  w(reg(4, kBcr), 0x00030004);  // 3 blocks of 4 words
  w(reg(4, kChcr), 0x01000201);
  EXPECT_TRUE(spu.received.empty());  // no request yet
  spu.request = true;
  run_for(200);  // picked up by the poll event
  ASSERT_EQ(spu.received.size(), 12u);
  for (u32 i = 0; i < 12; ++i) EXPECT_EQ(spu.received[i], i + 1);
  // MADR ends after the last block; BA counted down to zero; BS kept.
  EXPECT_EQ(r(reg(4, kMadr)), 0x3030u);
  EXPECT_EQ(r(reg(4, kBcr)), 0x00000004u);
  EXPECT_EQ(r(reg(4, kChcr)), 0x00000201u);
  EXPECT_EQ(r(kDicr), 0x80900000u | (1u << 28));
}

TEST_F(DmaTest, SyncMode1TriggerForcesFirstBlockOnly) {
  w(kDpcr, 0x00000800);
  gpu.request = false;
  w(reg(2, kMadr), 0);
  w(reg(2, kBcr), 0x00020002);
  w(reg(2, kChcr), 0x11000201);
  EXPECT_EQ(gpu.received.size(), 2u);
  EXPECT_EQ(r(reg(2, kBcr)), 0x00010002u);
  EXPECT_EQ(r(reg(2, kChcr)), 0x01000201u);  // trigger cleared at begin
}

// Sync mode 1 (fitted to ps1-tests dma/chopping, GPU): a block's words cost 0x120 clocks per
// 0x100 with the CPU held, then the CPU has the bus for 10 cycles before the next block.
TEST_F(DmaTest, SyncMode1Timing) {
  w(kDpcr, 0x00000800);
  w(reg(2, kMadr), 0);
  w(reg(2, kBcr), 0x00100010);  // 16 blocks x 16 words = 256 words
  Cycles t0 = sched.now();
  w(reg(2, kChcr), 0x01000201);
  EXPECT_EQ(gpu.received.size(), 16u);  // the first block, then the CPU runs
  EXPECT_EQ(sched.now() - t0, 18u);     // 16 x 0x120 / 0x100
  run_for(9);
  EXPECT_EQ(gpu.received.size(), 16u);
  run_for(1);
  EXPECT_EQ(gpu.received.size(), 32u);
  while (r(reg(2, kChcr)) & Dma::kChcrBusy) run_for(1);
  EXPECT_EQ(gpu.received.size(), 256u);
  EXPECT_EQ(sched.now() - t0, 16u * 18 + 15 * 10);
}

// A device that takes longer than the controller's gap over a block (the SPU draining its FIFO)
// is asked for the next one only when it is done; the CPU runs meanwhile.
TEST_F(DmaTest, SyncMode1WaitsForTheDeviceBetweenBlocks) {
  w(kDpcr, 0x00080000);
  spu.block_cycles_per_word = 32;
  w(reg(4, kMadr), 0);
  w(reg(4, kBcr), 0x00020010);  // 2 blocks of 16 words
  w(reg(4, kChcr), 0x01000201);
  EXPECT_EQ(spu.received.size(), 16u);
  run_for(16 * 32 - 1);
  EXPECT_EQ(spu.received.size(), 16u);
  run_for(1);
  EXPECT_EQ(spu.received.size(), 32u);
  EXPECT_EQ(r(reg(4, kChcr)) & Dma::kChcrBusy, 0u);
}

TEST_F(DmaTest, LinkedListSendsNodePayloads) {
  w(kDpcr, 0x00000800);
  w(kDicr, 0x00840000);
  // Node A (0x100): 2 words -> node B (0x200): 0 words -> node C (0x300): 3 words -> end.
  set_ram32(0x100, 0x02000200);
  set_ram32(0x104, 0x11111111);
  set_ram32(0x108, 0x22222222);
  set_ram32(0x200, 0x00000300);
  set_ram32(0x300, 0x03FFFFFF);
  set_ram32(0x304, 0x33333333);
  set_ram32(0x308, 0x44444444);
  set_ram32(0x30C, 0x55555555);
  set_ram32(0x310, 0x66666666);  // beyond the node: must not be sent
  w(reg(2, kMadr), 0x100);
  w(reg(2, kChcr), 0x01000401);
  std::vector<u32> expect = {0x11111111, 0x22222222, 0x33333333, 0x44444444, 0x55555555};
  EXPECT_EQ(gpu.received, expect);
  EXPECT_EQ(r(reg(2, kMadr)), 0x00FFFFFFu);
  EXPECT_EQ(r(kDicr), 0x80840000u | (1u << 26));
}

TEST_F(DmaTest, LinkedListEndsAtAnyNextAddressWithBit23) {
  // Any next-node address with bit 23 set ends the list, not only 0xFFFFFF. MADR keeps the end
  // marker as written, BCR is untouched and CHCR's start/busy bit is clear.
  w(kDpcr, 0x00000800);
  for (u32 marker : {0x800000u, 0x800001u, 0xFFFFF0u, 0xFFFFFFu}) {
    gpu.received.clear();
    set_ram32(0x100, 0x01000000 | marker);  // one word, then the end
    set_ram32(0x104, 0xC0DE0000 | (marker & 0xFF));
    w(kDicr, 0);
    w(reg(2, kBcr), 0x00123456);
    w(reg(2, kMadr), 0x100);
    w(reg(2, kChcr), 0x01000401);  // linked list, from RAM, start
    EXPECT_EQ(gpu.received, std::vector<u32>{0xC0DE0000 | (marker & 0xFF)}) << std::hex << marker;
    // Only 0xFFFFFF ends it cleanly; any other marker raises the bus error flag, bit 15, which
    // forces bit 31 (pcsx-redux src/mips/tests/dma, run on hardware).
    EXPECT_EQ(r(kDicr), marker == 0xFFFFFF ? 0u : 0x80008000u) << std::hex << marker;
    EXPECT_EQ(r(reg(2, kMadr)), marker) << std::hex << marker;
    EXPECT_EQ(r(reg(2, kBcr)), 0x00123456u) << std::hex << marker;
    EXPECT_EQ(r(reg(2, kChcr)), 0x00000401u) << std::hex << marker;
  }
}

TEST_F(DmaTest, LinkedListWaitsWhileTheDeviceStopsRequesting) {
  // A node whose payload makes the device drop its request (the GPU's DMA request follows
  // GPUSTAT: GP0(C0) starts a VRAM-to-CPU copy, psx-spx "GPU Status Register"): the next node
  // waits, MADR pointing at it, until the request returns (polled every 64 cycles).
  w(kDpcr, 0x00000800);
  gpu.busy_word = 0xC0000000;
  set_ram32(0x100, 0x01000200);
  set_ram32(0x104, 0xC0000000);
  set_ram32(0x200, 0x01000300);
  set_ram32(0x204, 0x22222222);
  set_ram32(0x300, 0x01FFFFFF);
  set_ram32(0x304, 0x33333333);
  w(reg(2, kMadr), 0x100);
  w(reg(2, kChcr), 0x01000401);
  EXPECT_EQ(gpu.received, std::vector<u32>{0xC0000000});
  EXPECT_EQ(r(reg(2, kMadr)), 0x200u);
  EXPECT_NE(r(reg(2, kChcr)) & Dma::kChcrBusy, 0u);
  run_for(200);
  EXPECT_EQ(gpu.received.size(), 1u);
  gpu.request = true;
  run_for(65);
  EXPECT_EQ(gpu.received, (std::vector<u32>{0xC0000000, 0x22222222, 0x33333333}));
  EXPECT_EQ(r(reg(2, kMadr)), 0x00FFFFFFu);
  EXPECT_EQ(r(reg(2, kChcr)) & Dma::kChcrBusy, 0u);
}

TEST_F(DmaTest, LinkedListTriggerForcesOneEmptyNodeOnly) {
  // Start/Trigger forces one node without a request; the next one waits for the device even when
  // the forced node delivered nothing (an ordering table's empty entry).
  w(kDpcr, 0x00000800);
  gpu.request = false;
  set_ram32(0x100, 0x00000200);
  set_ram32(0x200, 0x00000300);
  set_ram32(0x300, 0x01FFFFFF);
  set_ram32(0x304, 0x33333333);
  w(reg(2, kMadr), 0x100);
  w(reg(2, kChcr), 0x11000401);
  EXPECT_EQ(r(reg(2, kMadr)), 0x200u);
  EXPECT_TRUE(gpu.received.empty());
  gpu.request = true;
  run_for(65);
  EXPECT_EQ(gpu.received, std::vector<u32>{0x33333333});
  EXPECT_EQ(r(reg(2, kMadr)), 0x00FFFFFFu);
}

// Linked-list node costs (dma.cpp): a header holds the CPU 0x398/256 cycles, a node with words 5
// more before them and the GPU's 0x110 clocks per 0x100 words; after a batch of 128 nodes the CPU
// gets 6 cycles for each. 128 headers: 128 * 0x398 / 256 = 460 cycles held, then 768 for the CPU.
TEST_F(DmaTest, LinkedListNodesHoldTheCpuInBatchesWithItsGapsBetween) {
  // 300 empty nodes, then one with a word: batches of 128, 128 and 45 nodes. The last holds
  // (45 * 0x398 + 5 * 256 + 0x110) / 256 = 167.8 cycles: 2 * (460 + 768) + 167 = 2623.
  w(kDpcr, 0x00000800);
  for (u32 i = 0; i < 300; ++i) set_ram32(0x1000 + 4 * i, 0x1000 + 4 * (i + 1));
  set_ram32(0x1000 + 1200, 0x01FFFFFF);
  set_ram32(0x1000 + 1204, 0x44444444);
  w(reg(2, kMadr), 0x1000);
  const Cycles t0 = sched.now();
  w(reg(2, kChcr), 0x01000401);
  EXPECT_EQ(sched.now() - t0, 460u);
  EXPECT_EQ(r(reg(2, kMadr)), 0x1000u + 4 * 128);
  EXPECT_NE(r(reg(2, kChcr)) & Dma::kChcrBusy, 0u);
  while (r(reg(2, kChcr)) & Dma::kChcrBusy) run_for(1);
  EXPECT_EQ(sched.now() - t0, 2623u);
  EXPECT_EQ(gpu.received, std::vector<u32>{0x44444444});
}

TEST_F(DmaTest, LinkedListOfEmptyNodesEndingWithAnEmptyOne) {
  // 101 empty nodes, the last with the end marker, within one batch: 101 * 0x398 / 256 = 362.97
  // -> 362 cycles inside the CHCR write; then the channel is done and its flag set.
  w(kDpcr, 0x00000800);
  w(kDicr, 0x00840000);  // channel 2's interrupt enabled, master enable
  for (u32 i = 0; i < 100; ++i) set_ram32(0x1000 + 4 * i, 0x1000 + 4 * (i + 1));
  set_ram32(0x1000 + 400, 0x00FFFFFF);
  w(reg(2, kMadr), 0x1000);
  const Cycles t0 = sched.now();
  w(reg(2, kChcr), 0x01000401);
  EXPECT_EQ(sched.now() - t0, 362u);
  EXPECT_EQ(r(reg(2, kChcr)) & Dma::kChcrBusy, 0u);
  EXPECT_TRUE(gpu.received.empty());
  EXPECT_EQ(r(reg(2, kMadr)), 0x00FFFFFFu);
  EXPECT_NE(r(kDicr) & (1u << 26), 0u);
}

TEST_F(DmaTest, EndlessListOfEmptyNodesGivesTheCpuItsShare) {
  // An empty node pointing at itself runs until the CPU stops it. On the console a CPU loop took
  // 25632 cycles beside such a list against 16040 alone (ps1-tests dma/chain-looping): time
  // passes 1.598 times as fast as the CPU's own cycles (here one per run_for step).
  w(kDpcr, 0x00000800);
  set_ram32(0x100, 0x00000100);
  w(reg(2, kMadr), 0x100);
  const Cycles t0 = sched.now();
  w(reg(2, kChcr), 0x01000401);
  EXPECT_EQ(sched.now() - t0, 460u);  // the CHCR write returns after the first batch
  Cycles cpu = 0;
  for (; cpu < 100 * 768 - 384; ++cpu) run_for(1);
  EXPECT_NEAR(static_cast<double>(sched.now() - t0) / static_cast<double>(cpu), 25632.0 / 16040.0, 0.025);
  EXPECT_NE(r(reg(2, kChcr)) & Dma::kChcrBusy, 0u);
  EXPECT_EQ(r(reg(2, kMadr)), 0x100u);
}

TEST_F(DmaTest, LinkedListStopsAfterTheNodeThatEndsTheRequest) {
  // Empty nodes before and after a node whose word ends the device's request: the list waits at
  // the node after it.
  w(kDpcr, 0x00000800);
  gpu.busy_word = 0xC0000000;
  set_ram32(0x100, 0x00000200);
  set_ram32(0x200, 0x01000300);
  set_ram32(0x204, 0xC0000000);
  set_ram32(0x300, 0x00000400);
  set_ram32(0x400, 0x01FFFFFF);
  set_ram32(0x404, 0x55555555);
  w(reg(2, kMadr), 0x100);
  w(reg(2, kChcr), 0x01000401);
  EXPECT_EQ(gpu.received, std::vector<u32>{0xC0000000});
  EXPECT_EQ(r(reg(2, kMadr)), 0x300u);
}

TEST_F(DmaTest, BurstIntoRamWrapsAtItsEndAndDropsCodeOnBothSides) {
  // MADR 1FFFF8h, four words from the device: the last two land at 0 and 4 (RAM repeats every
  // 2 MiB, psx-spx "Memory Map"), and compiled code on both pages is dropped.
  CodePages pages;
  bus.attach_code_pages(&pages);
  pages.mark_compiled(0x001FFFFC, 0x001FFFFC);
  pages.mark_compiled(0x00000004, 0x00000004);
  w(kDpcr, 0x00008000);
  w(reg(3, kMadr), 0x1FFFF8);
  w(reg(3, kBcr), 4);
  w(reg(3, kChcr), 0x11000000);  // CD-ROM to RAM, sync mode 0, start + trigger
  EXPECT_EQ(ram32(0x1FFFF8), 0x100u);
  EXPECT_EQ(ram32(0x1FFFFC), 0x101u);
  EXPECT_EQ(ram32(0x0), 0x102u);
  EXPECT_EQ(ram32(0x4), 0x103u);
  EXPECT_EQ(pages.take_dirty(), (std::vector<u32>{0x1FFF, 0x0}));
  bus.attach_code_pages(nullptr);
}

TEST_F(DmaTest, BurstFromRamWrapsAtItsEnd) {
  // MADR 1FFFF8h, four words to the device: the last two come from 0 and 4 (RAM repeats every
  // 2 MiB, psx-spx "Memory Map").
  set_ram32(0x1FFFF8, 0xB0), set_ram32(0x1FFFFC, 0xB1), set_ram32(0x0, 0xB2), set_ram32(0x4, 0xB3);
  w(kDpcr, 0x00008000);
  w(reg(3, kMadr), 0x1FFFF8);
  w(reg(3, kBcr), 4);
  w(reg(3, kChcr), 0x11000001);  // RAM to CD-ROM, sync mode 0, start + trigger
  EXPECT_EQ(cdrom.received, (std::vector<u32>{0xB0, 0xB1, 0xB2, 0xB3}));
}

TEST_F(DmaTest, EndlessLinkedListDoesNotHangHost) {
  w(kDpcr, 0x00000800);
  set_ram32(0x100, 0x01000100);  // a node that points at itself
  w(reg(2, kMadr), 0x100);
  w(reg(2, kChcr), 0x01000401);
  EXPECT_NE(r(reg(2, kChcr)) & Dma::kChcrBusy, 0u);  // still going: the write returned
  size_t first = gpu.received.size();
  EXPECT_GT(first, 0u);
  run_for(800);
  EXPECT_GT(gpu.received.size(), first);  // continues after the CPU's gap
  w(reg(2, kChcr), 0);                    // the CPU stops it
  size_t stopped = gpu.received.size();
  run_for(2000);
  EXPECT_EQ(gpu.received.size(), stopped);
}

TEST_F(DmaTest, PriorityOrdersSimultaneousChannels) {
  std::vector<int> order;
  gpu.order = spu.order = mdec_in.order = &order;
  gpu.id = 2, spu.id = 4, mdec_in.id = 0;
  w(kDpcr, 0);
  w(reg(0, kBcr), 0x00010001);
  w(reg(0, kChcr), 0x01000201);
  w(reg(2, kBcr), 0x00010001);
  w(reg(2, kChcr), 0x01000201);
  w(reg(4, kBcr), 0x00010001);
  w(reg(4, kChcr), 0x01000201);
  // Priorities: DMA0 = 5, DMA2 = 1, DMA4 = 5 (tie with DMA0: higher channel number wins).
  w(kDpcr, 0x000D090D);
  std::vector<int> expect = {2, 4, 0};
  EXPECT_EQ(order, expect);
}

TEST_F(DmaTest, SaveStateRoundTrip) {
  w(kDpcr, 0x08000800);
  w(kDicr, 0x00C4003F);
  w(reg(2, kMadr), 0x1234);
  w(reg(2, kBcr), 0x00050010);
  gpu.request = false;
  w(reg(2, kChcr), 0x01000201);
  StateIO out;
  dma.do_state(out);
  Scheduler sched2;
  InterruptController irq2;
  Bus bus2{sched2, irq2};
  Dma dma2{sched2, irq2, bus2};
  StateIO in(out.buffer().data(), out.buffer().size());
  dma2.do_state(in);
  EXPECT_TRUE(in.at_end());
  for (u32 off : {reg(2, kMadr), reg(2, kBcr), reg(2, kChcr), kDpcr, kDicr})
    EXPECT_EQ(dma2.io_read(off, 4), dma.io_read(off, 4)) << off;
}

}  // namespace
}  // namespace psx
