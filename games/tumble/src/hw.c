/* System start-up and timing without the BIOS: interrupts masked, VBlank found by polling the
   interrupt controller's status register (psx-spx "Interrupt Control"), DMA waits. */
#include "hw.h"

void hw_init(void) {
  uint32_t sr;
  __asm__ volatile("mfc0 %0, $12\n\tnop" : "=r"(sr));
  sr &= ~1u;          /* IEc: no CPU interrupts */
  sr |= 1u << 30;     /* CU2: the GTE is usable */
  __asm__ volatile("mtc0 %0, $12\n\tnop\n\tnop" : : "r"(sr));
  I_MASK = 0;
  I_STAT = 0;         /* writing 0 acknowledges every pending line */
  DMA_DICR = 0;
  /* Enable GPU (ch 2), SPU (ch 4) and OTC (ch 6), keeping the reset priorities (psx-spx DPCR:
     bit 3+4n enables channel n). */
  DMA_DPCR |= (1u << 11) | (1u << 19) | (1u << 27);
}

/* The spin limit is a little over one frame of polling on real hardware (each uncached I/O read
   takes several cycles), so a missing VBlank costs about a frame instead of a hang. */
void hw_wait_vblank(void) {
  I_STAT = ~IRQ_VBLANK;
  for (uint32_t spin = 0; !(I_STAT & IRQ_VBLANK) && spin < 150000u; ++spin) {
  }
  I_STAT = ~IRQ_VBLANK;
}

void hw_wait_dma(int ch) {
  for (uint32_t spin = 0; (DMA_CHCR(ch) & CHCR_BUSY) && spin < 4000000u; ++spin) {
  }
}
