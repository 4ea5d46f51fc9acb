/* SPU set-up, uploads and voices (see spu.h). */
#include "spu.h"
#include "hw.h"

#define SPUCNT_ENABLE 0x8000
#define SPUCNT_UNMUTE 0x4000
#define SPUCNT_MODE_MASK 0x0030
#define SPUCNT_MANUAL_WRITE 0x0010
#define SPUSTAT_BUSY 0x0400

/* SPUSTAT mirrors the SPUCNT transfer mode once the SPU has applied it. Returns 0 if it never
   does (an SPU that does not answer must not hang the game). */
static int wait_mode(uint16_t mode) {
  for (uint32_t spin = 0; spin < 100000; ++spin)
    if ((SPU_STAT & SPUCNT_MODE_MASK) == mode) return 1;
  return 0;
}

static int wait_idle(void) {
  for (uint32_t spin = 0; spin < 100000; ++spin)
    if (!(SPU_STAT & SPUSTAT_BUSY)) return 1;
  return 0;
}

void spu_init(void) {
  SPU_CNT = 0;
  wait_mode(0);
  SPU_MAIN_VOL_L = 0;
  SPU_MAIN_VOL_R = 0;
  SPU_REVERB_VOL_L = 0;
  SPU_REVERB_VOL_R = 0;
  SPU_KOFF_LO = 0xFFFF;
  SPU_KOFF_HI = 0x00FF;
  SPU_PMON_LO = 0;
  SPU_NON_LO = 0;
  SPU_EON_LO = 0;
  SPU_EON_HI = 0;
  SPU_CD_VOL_L = 0;
  SPU_CD_VOL_R = 0;
  SPU_TRANSFER_CTRL = 0x0004;  /* normal transfer type (psx-spx: the usual value) */
  SPU_CNT = SPUCNT_ENABLE | SPUCNT_UNMUTE;
  wait_mode(0);
  SPU_MAIN_VOL_L = 0x3FFF;
  SPU_MAIN_VOL_R = 0x3FFF;
}

void spu_upload(uint32_t addr, const uint8_t *data, uint32_t bytes) {
  SPU_TRANSFER_ADDR = (uint16_t)(addr >> 3);
  uint32_t halfwords = bytes / 2;
  for (uint32_t i = 0; i < halfwords;) {
    /* The FIFO holds 32 halfwords; fill it, start a manual write, wait until it has drained. */
    for (int n = 0; n < 32 && i < halfwords; ++n, ++i) SPU_FIFO = (uint16_t)(data[2 * i] | data[2 * i + 1] << 8);
    SPU_CNT = (uint16_t)((SPU_CNT & ~SPUCNT_MODE_MASK) | SPUCNT_MANUAL_WRITE);
    int ok = wait_mode(SPUCNT_MANUAL_WRITE) && wait_idle();
    SPU_CNT = (uint16_t)(SPU_CNT & ~SPUCNT_MODE_MASK);
    if (!ok || !wait_mode(0)) return;
  }
}

void spu_play(int voice, uint32_t addr, uint32_t pitch, uint16_t volume) {
  SPU_VOICE(voice, 0x0) = volume;                  /* volume left */
  SPU_VOICE(voice, 0x2) = volume;                  /* volume right */
  SPU_VOICE(voice, 0x4) = (uint16_t)pitch;         /* sample rate */
  SPU_VOICE(voice, 0x6) = (uint16_t)(addr >> 3);   /* start address */
  SPU_VOICE(voice, 0x8) = 0x000F;                  /* ADSR: fastest attack, sustain level max */
  SPU_VOICE(voice, 0xA) = 0x0000;                  /* ADSR: sustain hold, fastest release */
  SPU_VOICE(voice, 0xE) = (uint16_t)(addr >> 3);   /* repeat address */
  SPU_KON_LO = (uint16_t)(1u << voice);
}
