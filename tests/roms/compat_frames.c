/* A picture that tells how many VBlanks the program has seen, for psxrl compat's tests
   (tests/unit/cli_compat_test.cpp): after each VBlank (I_STAT bit 0, polled and acknowledged
   by writing 0 to it: psx-spx "Interrupt Control") the whole 320x240 display is filled with a
   colour made from the count. It uses no BIOS call, so under the HLE kernel and under a boot ROM
   that side-loads it the last picture agrees only when both runs end on the same VBlank of the
   program. It never exits, so a compat run lasts all its frames. */
#include "gpu_rom.h"

#define I_STAT (*(volatile uint32_t *)0xBF801070)
#define IRQ_VBLANK 1u

int main(void) {
  gpu_init();
  I_STAT = ~IRQ_VBLANK; /* a VBlank before the program started is not one of its own */
  for (uint32_t count = 0;; ++count) {
    /* B G R: each count a different colour (the low byte steps by 40, the middle one by 1). */
    gp0(0x02000000 | ((count * 0x000128) & 0xFFFFFF));
    gp0(XY(0, 0));
    gp0(XY(320, 240));
    while (!(I_STAT & IRQ_VBLANK)) {
    }
    I_STAT = ~IRQ_VBLANK;
  }
}
