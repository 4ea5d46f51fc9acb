/* The timer calls take the timer number from the low halfword of their first argument, so the
   event classes F2000000h-F2000002h (RCntCNT0-2) that SDK libraries pass name timers 0-2, as in
   the retail BIOS's code (OpenBIOS copies it: pcsx-redux src/mips/openbios/handlers/irq.c); mode
   bits from psx-spx "BIOS Timer Functions": flags bit 12 sets IRQ on target (mode bit 4), flags
   bit 0 clear selects the clock source bit 8. GetRCnt does not mask: it returns 0 for t > 2. */
#include "bios_calls.h"
#include "psx/test.h"

#define T2_VALUE (*(volatile uint32_t *)0xBF801120)
#define T2_MODE (*(volatile uint32_t *)0xBF801124)
#define T2_TARGET (*(volatile uint32_t *)0xBF801128)

int main(void) {
  enter_critical_section();
  CHECK_EQ("SetRCnt(F2000002h) sets up timer 2", set_rcnt(0xF2000002, 0x1E05, 0x1000), 1);
  CHECK_EQ("timer 2 target", T2_TARGET & 0xFFFF, 0x1E05);
  CHECK_EQ("timer 2 mode: 48h | IRQ on target | clock bit 8", T2_MODE & 0x159, 0x158);
  CHECK_EQ("StartRCnt(F2000002h) returns 1", start_rcnt(0xF2000002), 1);
  CHECK_EQ("I_MASK bit 6 (timer 2) set", (I_MASK >> 6) & 1, 1);
  CHECK_EQ("StopRCnt(F2000002h) returns 1", stop_rcnt(0xF2000002), 1);
  CHECK_EQ("I_MASK bit 6 cleared", (I_MASK >> 6) & 1, 0);
  CHECK_EQ("SetRCnt of timer 3 (vblank) does nothing", set_rcnt(0xF2000003, 100, 0x1000), 0);
  exit_critical_section();
  return test_done("bios_rcnt_class");
}
