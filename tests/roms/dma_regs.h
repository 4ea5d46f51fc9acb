/* I/O registers used by the DMA, timer and MDEC test programs (psx-spx names, KSEG1 addresses). */
#ifndef DMA_REGS_H
#define DMA_REGS_H
#include <stdint.h>

#define IO32(a) (*(volatile uint32_t *)(a))
#define IO16(a) (*(volatile uint16_t *)(a))

#define I_STAT IO32(0xBF801070)
#define I_MASK IO32(0xBF801074)
#define D_MADR(n) IO32(0xBF801080 + (n)*0x10)
#define D_BCR(n) IO32(0xBF801084 + (n)*0x10)
#define D_CHCR(n) IO32(0xBF801088 + (n)*0x10)
#define DPCR IO32(0xBF8010F0)
#define DICR IO32(0xBF8010F4)
#define T_COUNT(n) IO16(0xBF801100 + (n)*0x10)
#define T_MODE(n) IO16(0xBF801104 + (n)*0x10)
#define T_COMP(n) IO16(0xBF801108 + (n)*0x10)
#define MDEC0 IO32(0xBF801820)
#define MDEC1 IO32(0xBF801824)

#define PHYS(p) ((uint32_t)(p)&0x00FFFFFF)

/* Waits (bounded) until a channel's Start/Busy bit clears; returns 0 on time-out. */
static inline int dma_wait(int ch) {
  for (int i = 0; i < 100000; ++i)
    if (!(D_CHCR(ch) & 0x01000000)) return 1;
  return 0;
}

#endif
