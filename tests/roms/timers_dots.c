/* Dots per scanline, as a console measures them (pcsx-redux src/mips/tests/timers, "Hardware
   verified on SCPH-5501"): timer 1 counting HBlanks and timer 0 counting dots, both reset by a
   MODE write one after the other; once timer 1 reads 50, dots / lines rounded is the dot clock's
   dots per line: 341/340 (256 pixels, NTSC/PAL), 426/426 (320), 487/486 (368), 682/681 (512),
   853/851 (640). psx-spx "GPU Timings" gives the arithmetic (3413 or 3406 video clocks a line over
   10, 8, 7, 5 or 4 video clocks a dot); the figures hold only if the first HBlank after the MODE
   write counts: a tick held back would make 50 lines last 51 (348 dots in 256-pixel NTSC). */
#include "dma_regs.h"
#include "gpu_rom.h"

#define LINES 50

static void wait_vblank(void) {
  I_STAT = ~1u;
  for (int i = 0; i < 3000000; ++i)
    if (I_STAT & 1) return;
  TEST_TIMEOUT("the VBlank IRQ (I_STAT.0)");
}

/* As the hardware test measures: a measurement that ends on an HBlank starts the next one just
   after it, so the first line is (almost) whole. */
static uint32_t dots_per_line(void) {
  T_MODE(1) = 0x0100; /* HBlank source */
  T_MODE(0) = 0x0100; /* dot clock source */
  T_MODE(1) = 0x0100;
  T_MODE(0) = 0x0100;
  for (int i = 0; T_COUNT(1) < LINES; ++i) {
    if (i == 1000000) {
      TEST_TIMEOUT("timer 1 to count 50 HBlanks");
      return 0;
    }
  }
  uint32_t dots = T_COUNT(0), lines = T_COUNT(1);
  return (dots + lines / 2) / lines;
}

/* GP1(08h) display mode `mode`, two frames to settle, a first measurement to line up with an
   HBlank, then the one checked. */
static void check_mode(const char *name, uint32_t mode, uint32_t expect) {
  GPU_GP1 = 0x08000000 | mode;
  wait_vblank();
  wait_vblank();
  dots_per_line();
  uint32_t dpl = dots_per_line();
  if (dpl != expect) tty_printf("%s: %u dots per line\n", name, dpl);
  CHECK_EQ(name, dpl, expect);
}

int main(void) {
  GPU_GP1 = 0x00000000;
  check_mode("256 NTSC", 0x00, 341);
  check_mode("256 PAL", 0x08, 340);
  check_mode("320 NTSC", 0x01, 426);
  check_mode("320 PAL", 0x09, 426);
  check_mode("368 NTSC", 0x40, 487);
  check_mode("368 PAL", 0x48, 486);
  check_mode("512 NTSC", 0x02, 682);
  check_mode("512 PAL", 0x0A, 681);
  check_mode("640 NTSC", 0x03, 853);
  check_mode("640 PAL", 0x0B, 851);
  GPU_GP1 = 0x08000001;
  T_MODE(0) = 0;
  T_MODE(1) = 0;
  return test_done("timers_dots");
}
