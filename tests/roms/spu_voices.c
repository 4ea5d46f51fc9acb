/* SPU test program: uploads ADPCM samples to sound RAM by manual FIFO writes (psx-spx "SPU RAM
   Manual Write"), plays them on two voices, and checks ENDX (End+Mute and End+Repeat blocks),
   ENVX after End+Mute, the RAM IRQ when a voice reads the IRQ address, its acknowledge, and key
   on clearing ENDX. spu_dma.c does the same with DMA channel 4 uploads. */
#include <stdint.h>

#include "psx/test.h"
#include "spu_regs.h"

#define I_STAT (*(volatile uint32_t *)0xBF801070)

/* Sample A: three blocks, the last End+Mute. Sample B: two blocks, LoopStart then End+Repeat.
   Shift 0 filter 0 with nibbles 7/9: a loud square-ish wave (psx-spx "Waveform Examples"). */
static uint8_t sample_a[48];
static uint8_t sample_b[32];

static void make_blocks(uint8_t *b, int blocks, uint8_t first_flags, uint8_t last_flags) {
  for (int i = 0; i < blocks * 16; ++i) b[i] = (i % 16 < 2) ? 0 : ((i / 4) & 1 ? 0x99 : 0x77);
  for (int k = 0; k < blocks; ++k) b[k * 16 + 1] = 0;
  b[1] |= first_flags;
  b[(blocks - 1) * 16 + 1] |= last_flags;
}

/* Manual write in runs of up to 32 halfwords (the FIFO size). */
static void upload_manual(uint32_t addr, const uint8_t *data, int bytes) {
  SPUCNT = CNT_ON;
  CHECK_EQ("stop mode applied", spu_wait_mode(0), 1);
  TSA = (uint16_t)(addr / 8);
  for (int pos = 0; pos < bytes;) {
    int n = 0;
    for (; n < 32 && pos < bytes; ++n, pos += 2) FIFO = (uint16_t)(data[pos] | data[pos + 1] << 8);
    SPUCNT = CNT_ON | 0x10;
    int i = 0;
    while ((SPUSTAT & 0x400) && ++i < 100000) {
    }
    if (i == 100000) TEST_TIMEOUT("SPUSTAT.10 (data transfer busy) to clear");
    SPUCNT = CNT_ON;
    if (!spu_wait_mode(0)) TEST_TIMEOUT("SPUSTAT bits 0-5 to show transfer mode 0");
  }
}

static int wait_endx(uint16_t mask) {
  for (int i = 0; i < 2000000; ++i)
    if ((ENDX0 & mask) == mask) return 1;
  return 0;
}

int main(void) {
  RAMCTRL = 0x0004;
  SPUCNT = CNT_ON;
  MVOLL = 0x3FFF;
  MVOLR = 0x3FFF;
  make_blocks(sample_a, 3, 0, 1);
  make_blocks(sample_b, 2, 4, 3);
  upload_manual(0x1000, sample_a, sizeof sample_a);
  upload_manual(0x2000, sample_b, sizeof sample_b);

  spu_setup_voice(0, 0x1000);
  spu_setup_voice(1, 0x2000);
  IRQA = 0x2010 / 8; /* second block of sample B */
  I_STAT = ~(1u << 9);
  SPUCNT = CNT_ON | 0x40;
  CHECK_EQ("no IRQ before key on", I_STAT & (1u << 9), 0);
  KON0 = 0x0003;
  KON1 = 0;

  CHECK_EQ("ENDX of both voices", wait_endx(0x0003), 1);
  CHECK_EQ("ENDX value", ENDX0 & 0x0003, 0x0003);
  CHECK_EQ("End+Mute zeroes ENVX", VOICE(0, 0xC), 0);
  CHECK_EQ("End+Repeat keeps playing", VOICE(1, 0xC) != 0, 1);
  CHECK_EQ("LSAX from LoopStart", VOICE(1, 0xE), 0x2000 / 8);
  CHECK_EQ("IRQ9 in I_STAT", I_STAT & (1u << 9), 1u << 9);
  CHECK_EQ("IRQ flag in SPUSTAT", SPUSTAT & 0x40, 0x40);

  SPUCNT = CNT_ON; /* acknowledge */
  I_STAT = ~(1u << 9);
  CHECK_EQ("IRQ flag acknowledged", SPUSTAT & 0x40, 0);
  CHECK_EQ("I_STAT acknowledged", I_STAT & (1u << 9), 0);

  KON0 = 0x0001; /* key on clears ENDX for voice 0 */
  int cleared = 0;
  for (int i = 0; i < 100000 && !cleared; ++i) cleared = (ENDX0 & 1) == 0;
  CHECK_EQ("key on clears ENDX", cleared, 1);
  return test_done("spu_voices");
}
