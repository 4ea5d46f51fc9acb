/* Smallest test program: prints a greeting through the debug TTY port (the test runner checks
   the text, tests/roms/cpu.cmake) and checks what the EXE loader and crt0 promise every program:
   its initialised data in place and its BSS cleared. */
#include "psx/test.h"

static volatile uint32_t initialised = 0x600DF00D; /* .data: loaded from the EXE */
static volatile uint32_t zeroed;                   /* .bss: cleared by crt0 */

int main(void) {
  tty_puts("hello from the PlayStation\n");
  CHECK_EQ("initialised data loaded from the EXE", initialised, 0x600DF00D);
  CHECK_EQ("BSS cleared by crt0", zeroed, 0);
  return test_done("hello");
}
