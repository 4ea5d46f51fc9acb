/* Booted from a disc made by mkdisc (no EXE given to psxrl): reaching main proves SYSTEM.CNF was
   read through ISO 9660 and BOOT loaded; the stack must be the STACK value of its SYSTEM.CNF. */
#include <stdint.h>

#include "psx/test.h"

int main(void) {
  uint32_t sp;
  __asm__ volatile("move %0, $sp" : "=r"(sp));
  tty_printf("booted from disc\n");
  CHECK_EQ("stack below SYSTEM.CNF STACK", sp <= 0x801FFE00u && sp > 0x801FF000u, 1);
  return test_done("cdrom_boot");
}
