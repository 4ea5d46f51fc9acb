/* The HLE kernel's BIOS calls, made through the A0h/B0h vectors and SYSCALL exactly as SDK code
   makes them. The printed text is checked by CTest against the C-standard printf results
   written out in tests/roms/cpu.cmake; return values are checked here. */
#include "psx/test.h"

uint32_t bios_strlen(const char *s);
void *bios_memcpy(void *d, const void *s, uint32_t n);
void *bios_memset(void *d, int c, uint32_t n);
int bios_putchar(int c);
int bios_puts(const char *s);
int bios_printf(const char *fmt, ...);
int std_out_putchar(int c);
int std_out_puts(const char *s);
uint32_t enter_critical_section(void);
void exit_critical_section(void);

static char buf[16];

static uint32_t sr(void) {
  uint32_t v;
  __asm__ volatile("mfc0 %0, $12\n\tnop" : "=r"(v));
  return v;
}

int main(void) {
  bios_putchar('A');
  std_out_putchar('B');
  bios_putchar('\n');
  bios_puts("puts line");
  std_out_puts("std_out_puts line");
  bios_printf("[%d|%i|%u|%x|%X|%o]\n", -42, 7, 3000000000u, 0xbeef, 0xbeef, 8);
  bios_printf("[%5d|%-5d|%05d|%+d|% d]\n", 42, 42, 42, 42, 42);
  bios_printf("[%#x|%#o|%.3d|%8.3s|%-4c|%%]\n", 255, 8, 7, "abcdef", 'z');
  bios_printf("[%*d|%s|%c%c]\n", 6, -12, "six", 'o', 'k');
  int n = bios_printf("%d %d %d %d %d %d\n", 1, 2, 3, 4, 5, 6); /* arguments 5+ come from the stack */
  CHECK_EQ("printf returns the length", n, 12);

  CHECK_EQ("strlen", bios_strlen("psxrl"), 5);
  bios_memset(buf, 'x', 4);
  CHECK_EQ("memset", buf[0] == 'x' && buf[3] == 'x' && buf[4] == 0, 1);
  CHECK_EQ("memcpy returns dst", (uint32_t)bios_memcpy(buf + 8, "hi", 3), (uint32_t)(buf + 8));
  CHECK_EQ("memcpy copies", buf[8] == 'h' && buf[9] == 'i', 1);

  /* The program starts inside a critical section, as a BIOS's boot leaves it (OpenBIOS
     main/main.c: EnterCriticalSection before Exec): SR.IEc and IM2 clear, so EnterCriticalSection
     reports that interrupts were disabled (psx-spx "SYS(01h)"). ExitCriticalSection sets both;
     EnterCriticalSection then clears them and reports that they were enabled. */
  CHECK_EQ("boot SR.IEc and IM2", sr() & 0x401, 0);
  CHECK_EQ("EnterCriticalSection at boot returns 0", enter_critical_section(), 0);
  exit_critical_section();
  CHECK_EQ("SR.IEc and IM2 after exit", sr() & 0x401, 0x401);
  CHECK_EQ("EnterCriticalSection returns 1", enter_critical_section(), 1);
  CHECK_EQ("SR.IEc after enter", sr() & 1, 0);
  CHECK_EQ("EnterCriticalSection again returns 0", enter_critical_section(), 0);
  exit_critical_section();
  CHECK_EQ("SR.IEc after exit", sr() & 1, 1);
  return test_done("bios_hle");
}
