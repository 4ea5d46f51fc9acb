/* What the benchmarks' 3D programs share: COP2 enabled (SR bit 30, psx-spx "COP0 - Status
   Register") and a 320x240 NTSC 15-bit display with the GP1(06)/(07) default ranges
   (psx-spx "GPU Display Control Commands"). */
#ifndef BENCH_VIDEO_H
#define BENCH_VIDEO_H
#include <stdint.h>

#define GP0 (*(volatile uint32_t *)0x1F801810)
#define GP1 (*(volatile uint32_t *)0x1F801814)

static inline void enable_gte(void) {
  uint32_t sr;
  __asm__ volatile("mfc0 %0, $12" : "=r"(sr));
  sr |= 1u << 30; /* CU2 */
  __asm__ volatile("mtc0 %0, $12\n\tnop\n\tnop" : : "r"(sr));
}

static inline void display_320x240(void) {
  GP1 = 0x00000000; /* reset */
  GP1 = 0x08000001; /* 320x240, NTSC, 15-bit */
  GP1 = 0x06C60260; /* horizontal display range */
  GP1 = 0x07042018; /* vertical display range */
  GP1 = 0x03000000; /* display on */
}

#endif
