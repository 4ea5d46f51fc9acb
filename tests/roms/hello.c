/* Smallest test program: prints through the debug TTY port and the HLE/BIOS putchar path. */
#include "psx/test.h"

int main(void) {
  tty_puts("hello from the PlayStation\n");
  CHECK_EQ("arithmetic", 6 * 7, 42);
  return test_done("hello");
}
