/* SPU registers used by the SPU test programs (psx-spx "SPU Control and Status Register",
   "SPU Voice Registers", "SPU Memory Access"; KSEG1 addresses). */
#ifndef SPU_REGS_H
#define SPU_REGS_H
#include <stdint.h>

#define SPU16(a) (*(volatile uint16_t *)(a))
#define VOICE(v, r) SPU16(0xBF801C00 + (v) * 16 + (r))
#define MVOLL SPU16(0xBF801D80)
#define MVOLR SPU16(0xBF801D82)
#define KON0 SPU16(0xBF801D88)
#define KON1 SPU16(0xBF801D8A)
#define ENDX0 SPU16(0xBF801D9C)
#define IRQA SPU16(0xBF801DA4)
#define TSA SPU16(0xBF801DA6)
#define FIFO SPU16(0xBF801DA8)
#define SPUCNT SPU16(0xBF801DAA)
#define RAMCTRL SPU16(0xBF801DAC)
#define SPUSTAT SPU16(0xBF801DAE)

#define CNT_ON 0xC000 /* SPU enable, unmute */

/* Waits (bounded) until SPUSTAT bits 0-5 show the transfer mode written to SPUCNT. */
static inline int spu_wait_mode(uint16_t mode) {
  for (int i = 0; i < 100000; ++i)
    if ((SPUSTAT & 0x3F) == mode) return 1;
  return 0;
}

/* Voice at 44.1 kHz (one ADPCM sample per output sample), full volume, fast attack, sustain
   level 15 that never steps down. */
static inline void spu_setup_voice(int v, uint32_t addr) {
  VOICE(v, 0x0) = 0x3FFF;
  VOICE(v, 0x2) = 0x3FFF;
  VOICE(v, 0x4) = 0x1000;
  VOICE(v, 0x6) = (uint16_t)(addr / 8);
  VOICE(v, 0x8) = 0x00FF;
  VOICE(v, 0xA) = 0x1FC0;
}

#endif
