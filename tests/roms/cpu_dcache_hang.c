/* In data-cache mode (BCC RAM clear, DS set) a load from the scratchpad's addresses hangs the bus
   until a power cycle (psx-spx "Memory Control", "D-cache" mode): the console must stop there with
   a message, so nothing after the load runs. */
#include "psx/test.h"

int main(void) {
  volatile uint32_t *bcc = (volatile uint32_t *)0xFFFE0130;
  *bcc = (*bcc & ~0x08u) | 0x80u;
  uint32_t v = *(volatile uint32_t *)0x1F800000;
  tty_printf("the load returned 0x%08x\n", v);
  return 0;
}
