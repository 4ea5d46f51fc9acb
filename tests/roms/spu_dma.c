/* SPU through DMA: ADPCM samples go to sound RAM by DMA channel 4 block mode (psx-spx "SPU RAM
   DMA-Write", SPUCNT transfer mode 2) and come back by DMA4 reads (mode 3); the RAM IRQ fires
   when a transfer touches the IRQ address (psx-spx "SPU Interrupt"); the samples are played on
   two voices and ENDX, ENVX, LSAX and IRQ9 are checked as spu_voices.c does for manual writes,
   plus the time voice 0 takes to reach its end block, measured on root counter 2. */
#include "dma_regs.h"
#include "psx/test.h"
#include "spu_regs.h"

#define DMA_SPU 4
#define ADDR_A 0x1000
#define ADDR_B 0x2000

/* Four 16-byte ADPCM blocks each (16 words = one DMA block of 10h words). Sample A ends with
   End+Mute; sample B has LoopStart on its first block and End+Repeat on its last. Shift 0
   filter 0 with nibbles 7/9: a loud square-ish wave (psx-spx "Waveform Examples"). */
static uint32_t sample_a[16];
static uint32_t sample_b[16];
static uint32_t readback[16];

static void make_blocks(uint32_t *words, uint8_t first_flags, uint8_t last_flags) {
  uint8_t *b = (uint8_t *)words;
  for (int i = 0; i < 64; ++i) b[i] = (i % 16 < 2) ? 0 : ((i / 4) & 1 ? 0x99 : 0x77);
  b[1] = first_flags;
  b[3 * 16 + 1] = last_flags;
}

static void spu_transfer(uint32_t addr, uint32_t *ram, uint16_t mode, uint32_t chcr, uint16_t extra_cnt) {
  SPUCNT = CNT_ON;
  CHECK_EQ("stop mode applied", spu_wait_mode(0), 1);
  TSA = (uint16_t)(addr / 8);
  SPUCNT = CNT_ON | extra_cnt | mode;
  CHECK_EQ("transfer mode applied", spu_wait_mode(mode), 1);
  /* SPUSTAT bit 7 follows SPUCNT bit 5; bit 8 = DMA write request, bit 9 = DMA read request. */
  CHECK_EQ("spustat dma request bits", SPUSTAT & 0x380, mode == 0x20 ? 0x180 : 0x280);
  D_MADR(DMA_SPU) = PHYS(ram);
  D_BCR(DMA_SPU) = 0x00010010; /* one block of 10h words */
  D_CHCR(DMA_SPU) = chcr;
  CHECK_EQ("dma4 done", dma_wait(DMA_SPU), 1);
  CHECK_EQ("dma4 madr advanced", D_MADR(DMA_SPU), PHYS(ram) + 64);
  CHECK_EQ("dma4 ba zero", D_BCR(DMA_SPU) >> 16, 0);
  CHECK_EQ("tsa reads back", TSA, addr / 8);
  SPUCNT = CNT_ON | extra_cnt;
}

static void upload_and_read_back(void) {
  DPCR |= 1u << (DMA_SPU * 4 + 3);
  DICR = 0x00900000; /* master enable + channel 4 */
  I_STAT = 0;
  spu_transfer(ADDR_A, sample_a, 0x20, 0x01000201, 0);
  CHECK_EQ("dma4 dicr flag", DICR, 0x90900000);
  CHECK_EQ("dma4 irq3", I_STAT & 8, 8);
  DICR = 0;
  spu_transfer(ADDR_B, sample_b, 0x20, 0x01000201, 0);
  for (int i = 0; i < 16; ++i) readback[i] = 0;
  spu_transfer(ADDR_A, readback, 0x30, 0x01000200, 0);
  for (int i = 0; i < 16; ++i) CHECK_EQ("dma read sample a", readback[i], sample_a[i]);
  spu_transfer(ADDR_B, readback, 0x30, 0x01000200, 0);
  for (int i = 0; i < 16; ++i) CHECK_EQ("dma read sample b", readback[i], sample_b[i]);
}

static void transfer_irq(void) {
  /* A DMA write over the IRQ address raises IRQ9 when SPUCNT bit 6 is set; acknowledging by
     clearing bit 6. The same write with bit 6 clear raises nothing. */
  IRQA = (ADDR_B + 0x20) / 8;
  I_STAT = ~(1u << 9);
  spu_transfer(ADDR_B, sample_b, 0x20, 0x01000201, 0);
  CHECK_EQ("no transfer irq when disabled", I_STAT & (1u << 9), 0);
  spu_transfer(ADDR_B, sample_b, 0x20, 0x01000201, 0x40);
  CHECK_EQ("transfer irq9", I_STAT & (1u << 9), 1u << 9);
  CHECK_EQ("transfer irq flag", SPUSTAT & 0x40, 0x40);
  SPUCNT = CNT_ON;
  I_STAT = ~(1u << 9);
  CHECK_EQ("transfer irq acknowledged", SPUSTAT & 0x40, 0);
}

int main(void) {
  RAMCTRL = 0x0004;
  SPUCNT = CNT_ON;
  MVOLL = 0x3FFF;
  MVOLR = 0x3FFF;
  make_blocks(sample_a, 0, 1);
  make_blocks(sample_b, 4, 3);
  upload_and_read_back();
  transfer_irq();

  spu_setup_voice(0, ADDR_A);
  spu_setup_voice(1, ADDR_B);
  IRQA = (ADDR_B + 0x10) / 8; /* second block of sample B */
  I_STAT = ~(1u << 9);
  SPUCNT = CNT_ON | 0x40;
  CHECK_EQ("no IRQ before key on", I_STAT & (1u << 9), 0);
  T_MODE(2) = 0x0200; /* system clock / 8 */
  KON0 = 0x0003;
  KON1 = 0;
  uint32_t t0 = T_COUNT(2), t_end = 0;
  for (int i = 0; i < 2000000 && (ENDX0 & 3) != 3; ++i)
    if (!t_end && (ENDX0 & 1)) t_end = T_COUNT(2);
  if (!t_end && (ENDX0 & 1)) t_end = T_COUNT(2);
  /* Voice 0 steps one ADPCM sample per 768-clock output sample (pitch 1000h): its End block is
     samples 84..111 (28 per block), so ENDX rises between 84 and 112 samples after key on, plus
     up to a block of start-up latency: 84*768/8 = 8064 to (112+28)*768/8 = 13440 ticks. */
  uint32_t ticks = (t_end - t0) & 0xFFFF;
  if (ticks < 8064 || ticks > 13440) tty_printf("ENDX after %u ticks of sysclock/8\n", ticks);
  CHECK_EQ("ENDX time >= 84 samples", ticks >= 8064, 1);
  CHECK_EQ("ENDX time <= 140 samples", ticks <= 13440, 1);
  CHECK_EQ("ENDX of both voices", ENDX0 & 0x0003, 0x0003);
  CHECK_EQ("End+Mute zeroes ENVX", VOICE(0, 0xC), 0);
  CHECK_EQ("End+Repeat keeps playing", VOICE(1, 0xC) != 0, 1);
  CHECK_EQ("LSAX from LoopStart", VOICE(1, 0xE), ADDR_B / 8);
  CHECK_EQ("IRQ9 from voice read", I_STAT & (1u << 9), 1u << 9);
  CHECK_EQ("IRQ flag in SPUSTAT", SPUSTAT & 0x40, 0x40);
  SPUCNT = CNT_ON;
  I_STAT = ~(1u << 9);
  KON0 = 0x0001; /* key on clears ENDX for voice 0 */
  int cleared = 0;
  for (int i = 0; i < 100000 && !cleared; ++i) cleared = (ENDX0 & 1) == 0;
  CHECK_EQ("key on clears ENDX", cleared, 1);
  return test_done("spu_dma");
}
