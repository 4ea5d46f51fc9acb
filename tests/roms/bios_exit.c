/* exit (A(06h), B(38h)) and _exit (A(3Ah)) (psx-spx "BIOS Misc Functions"): the program ends
   with its code; a BIOS then hangs, the HLE kernel stops the console with the code. Built once
   per call (EXIT_CALL); rom.bios_exit* expect the code 7 and the kernel's message. */
#include "bios_stdlib_calls.h"
#include "psx/tty.h"

int main(void) {
  tty_printf("calling the exit function\n");
  EXIT_CALL(7);
  tty_printf("the exit function returned\n");
  return 1;
}
