/* BIOS putchar calls (A0h:3Ch, B0h:3Dh) print even when a BIOS, not the HLE kernel, runs: the
   emulator hooks the call and lets the BIOS continue (run with the project's boot ROM). */
#include "psx/tty.h"

int bios_putchar(int c);
int std_out_putchar(int c);

int main(void) {
  bios_putchar('o');
  std_out_putchar('k');
  bios_putchar('\n');
  return 0;
}
