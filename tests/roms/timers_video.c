/* Root counters driven by the GPU's video signals (psx-spx "Timers", "GPU Timings"): timer 1
   counting HBlanks between VBlank IRQs (263 lines per NTSC progressive frame), timer 0 on the
   320/368/640-pixel dot clocks against the system clock, and the HBlank/VBlank sync modes. The
   expected counts are derived in the comments from the documented timing. */
#include "dma_regs.h"
#include "gpu_rom.h"

#define NTSC_LINES 263

static void spin(int n) {
  for (volatile int i = 0; i < n; ++i) {
  }
}

/* Acknowledges IRQ0 and waits for the next VBlank start; 0 on time-out (also a failure). */
static int wait_vblank(void) {
  I_STAT = ~1u;
  for (int i = 0; i < 3000000; ++i)
    if (I_STAT & 1) return 1;
  TEST_TIMEOUT("the VBlank IRQ (I_STAT.0)");
  return 0;
}

/* Waits `ticks` x 8 system clocks on timer 2 (system clock / 8). Every poll takes at least one
   clock, so ticks x 8 polls (plus slack) are more than enough. */
static void wait_sys8(uint32_t ticks) {
  T_MODE(2) = 0x0200;
  uint32_t polls = 0, limit = ticks * 8 + 10000;
  while (T_COUNT(2) < ticks && ++polls < limit) {
  }
  if (polls == limit) TEST_TIMEOUT("timer 2 (system clock / 8) to count up");
}

static void hblanks_per_frame(void) {
  /* Timer 1 on HBlank: one tick per scanline, hblank also during vertical blanking, so a frame
     from VBlank IRQ to VBlank IRQ is 263 ticks in NTSC non-interlaced mode. Five frames in a row
     also show one VBlank IRQ per frame. */
  T_MODE(1) = 0x0100;
  CHECK_EQ("vblank irq", wait_vblank(), 1);
  uint32_t a = T_COUNT(1);
  for (int k = 0; k < 5; ++k) {
    CHECK_EQ("vblank irq each frame", wait_vblank(), 1);
    uint32_t b = T_COUNT(1);
    CHECK_EQ("hblanks per frame", (b - a) & 0xFFFF, NTSC_LINES);
    a = b;
  }
}

/* Timer 2 on the system clock is the reference; reads it, timer 0, then it again: timer 0 must
   lie between the two reference readings times num/den, give or take `tol` dots. The spin must
   stay under timer 2's 65536 counts: each pass of its loop loads the counter twice from the stack
   and uses it after the delay slot, 21 cycles with loads timed as measured (the load shadow,
   src/core/cpu/cpu.h), so 2000 passes take about 42000 cycles, still past the 30000 that the
   tolerance argument below needs. */
static void check_dots(const char *what, uint32_t num, uint32_t den, uint32_t tol) {
  T_MODE(0) = 0x0100;
  T_MODE(2) = 0x0000;
  spin(2000);
  uint32_t r0 = T_COUNT(2);
  uint32_t d = T_COUNT(0);
  uint32_t r1 = T_COUNT(2);
  uint32_t lo = (uint32_t)((uint64_t)r0 * num / den), hi = (uint32_t)((uint64_t)r1 * num / den);
  if (!(d + tol >= lo && d <= hi + tol)) tty_printf("%s: %u dots, expected %u..%u\n", what, d, lo, hi);
  CHECK_EQ(what, d + tol >= lo && d <= hi + tol, 1);
}

static void dot_clocks(void) {
  /* Dot clock = video clock / divider, the same video clock that times the scanlines (psx-spx
     "GPU Timings": NTSC 53.693175 MHz, 3413 video cycles per line, 320pix/NTSC 3413/8 = 426.625
     dots per line). 53693175 / 33868800 = 715909 / 451584 video clocks per CPU clock, so
     dots = cycles * 715909 / (451584 * divider). (A video clock of CPU * 11/7 would give 423 dots
     per 320-pixel line, 0.8% slow: outside the tolerance after 30000 cycles.) */
  GPU_GP1 = 0x08000001; /* 320 pixels: divider 8 */
  check_dots("dotclock 320", 715909, 451584 * 8, 2);
  GPU_GP1 = 0x08000003; /* 640 pixels: divider 4 */
  check_dots("dotclock 640", 715909, 451584 * 4, 2);
  GPU_GP1 = 0x08000040; /* 368 pixels: divider 7 */
  check_dots("dotclock 368", 715909, 451584 * 7, 2);
  GPU_GP1 = 0x08000001;
  T_MODE(0) = 0;
}

static void reset_at_hblank(void) {
  /* Timer 0, system clock, sync mode 1 (reset at HBlank start): the largest value seen is one
     scanline less the polling gap: 2152.5 CPU cycles per NTSC scanline (psx-spx "Horizontal
     Timings": 3412.5 video cycles at 53.693175 MHz), so lines last 2152 or 2153 cycles and the
     counter never exceeds 2152. Values just after a reset are seen too. A 11/7 video clock
     would give 2172. */
  uint32_t max = 0, min = 0xFFFF;
  T_MODE(0) = 0x0003;
  for (int i = 0; i < 2000; ++i) {
    uint32_t v = T_COUNT(0);
    if (v > max) max = v;
    if (v < min) min = v;
  }
  if (max > 2152 || max < 2152 - 64) tty_printf("reset at hblank: max %u\n", max);
  CHECK_EQ("reset at hblank: max <= line", max <= 2152, 1);
  CHECK_EQ("reset at hblank: max near line", max >= 2152 - 64, 1);
  CHECK_EQ("reset at hblank: resets seen", min < 64, 1);
  T_MODE(0) = 0;
}

static void vblank_sync_modes(void) {
  /* Timer 1 on HBlank, sync mode 1 (reset at VBlank): 280000 cycles after the VBlank IRQ the
     count is 280000 / 2152.5 = 130.08 lines, 129..131 with the phase of the first HBlank. */
  T_MODE(1) = 0x0103;
  wait_vblank();
  wait_sys8(35000);
  uint32_t v = T_COUNT(1);
  if (v < 129 || v > 131) tty_printf("reset at vblank: %u lines\n", v);
  CHECK_EQ("reset at vblank", v >= 129 && v <= 131, 1);
  /* Sync mode 2 (reset at VBlank, pause outside it) counts the lines inside VBlank; sync mode 0
     (pause during VBlank) counts the lines outside it, frame to frame: together one frame. */
  T_MODE(1) = 0x0105;
  wait_vblank();
  wait_sys8(35000);
  uint32_t inside = T_COUNT(1);
  wait_sys8(25000);
  CHECK_EQ("paused outside vblank", T_COUNT(1), inside);
  T_MODE(1) = 0x0101;
  wait_vblank();
  uint32_t a = T_COUNT(1);
  wait_vblank();
  uint32_t outside = (T_COUNT(1) - a) & 0xFFFF;
  CHECK_EQ("inside + outside vblank = frame", inside + outside, NTSC_LINES);
  CHECK_EQ("some lines in vblank", inside > 0 && outside > 0, 1);
  /* Sync mode 3 (pause until VBlank, then free run): still 0 mid-frame, counting after the
     VBlank, then 263 per frame. */
  wait_vblank();
  wait_sys8(10000);
  T_MODE(1) = 0x0107;
  wait_sys8(20000);
  CHECK_EQ("paused until vblank", T_COUNT(1), 0);
  wait_vblank();
  wait_vblank();
  a = T_COUNT(1);
  CHECK_EQ("counting after vblank", a > 0, 1);
  wait_vblank();
  CHECK_EQ("free run after vblank", (T_COUNT(1) - a) & 0xFFFF, NTSC_LINES);
  T_MODE(1) = 0;
}

int main(void) {
  GPU_GP1 = 0x00000000;
  GPU_GP1 = 0x08000001; /* 320x240 NTSC, non-interlaced */
  hblanks_per_frame();
  dot_clocks();
  reset_at_hblank();
  vblank_sync_modes();
  return test_done("timers_video");
}
