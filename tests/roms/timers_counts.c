/* Root counter test program: each clock source counts what the clock ratios predict over an
   interval measured with another counter, COMP/0xFFFF flags and IRQs, one-shot, toggle mode and
   timer 2's stop/free-run sync settings (psx-spx "Timers"). */
#include "dma_regs.h"
#include "psx/test.h"

static void spin(int n) {
  for (volatile int i = 0; i < n; ++i) {
  }
}

/* Reads timer `a`, then `b`, then `a` again; `b` must lie between the two readings of `a` scaled
   by num/den, give or take `tol` ticks (the counters were started a few clocks apart). */
static void check_ratio(const char *what, int a, int b, uint32_t num, uint32_t den, uint32_t tol) {
  uint32_t a0 = T_COUNT(a);
  uint32_t bv = T_COUNT(b);
  uint32_t a1 = T_COUNT(a);
  /* 64-bit products: the dot clock ratio's numerator is six digits. */
  uint32_t lo = (uint32_t)((uint64_t)a0 * num / den), hi = (uint32_t)((uint64_t)a1 * num / den);
  if (!(bv + tol >= lo && bv <= hi + tol)) tty_printf("%s: %u between %u and %u?\n", what, bv, lo, hi);
  CHECK_EQ(what, bv + tol >= lo && bv <= hi + tol, 1);
}

static void test_sources(void) {
  /* Timer 1 on the system clock is the reference. Timer 0 on the dotclock: the NTSC video clock
     (psx-spx "GPU Timings": 53.693175 MHz) over the 33.8688 MHz CPU clock is 715909/451584
     video clocks per CPU clock; 10 video clocks per dot in the reset 256-pixel mode (psx-spx:
     3413/10 = 341.3 dots per 3413-cycle line), so 715909/4515840 dots per CPU clock. */
  T_MODE(0) = 0x0100;
  T_MODE(1) = 0x0000;
  spin(2000);
  check_ratio("dotclock 256", 1, 0, 715909, 4515840, 1);
  /* Timer 2 with the /8 prescaler against timer 1. */
  T_MODE(1) = 0x0000;
  T_MODE(2) = 0x0200;
  spin(2000);
  check_ratio("sysclock/8", 1, 2, 1, 8, 1);
  /* Timer 2 on the system clock counts with timer 1. */
  T_MODE(1) = 0x0000;
  T_MODE(2) = 0x0000;
  spin(2000);
  check_ratio("sysclock", 1, 2, 1, 1, 8);
}

static void test_target_period(void) {
  /* ZRET with COMP = 999: one COMP IRQ every 999 + 2 clocks (psx-spx "Reset and Wrap"). The
     interval between two IRQs is measured on timer 1; the polling loop adds a few clocks. */
  I_STAT = 0;
  T_COMP(2) = 999;
  T_MODE(2) = 0x0058; /* ZRET | CMP | REPT */
  T_MODE(1) = 0x0000;
  int n = 0;
  while (!(I_STAT & 0x40) && ++n < 100000) {
  }
  uint32_t first = T_COUNT(1);
  if (n == 100000) TEST_TIMEOUT("the first timer 2 IRQ (I_STAT.6)");
  I_STAT = ~0x40u;
  n = 0;
  while (!(I_STAT & 0x40) && ++n < 100000) {
  }
  uint32_t second = T_COUNT(1);
  if (n == 100000) TEST_TIMEOUT("the second timer 2 IRQ (I_STAT.6)");
  uint32_t period = (second - first) & 0xFFFF;
  CHECK_EQ("period >= 1001 - poll", period + 40 >= 1001, 1);
  CHECK_EQ("period <= 1001 + poll", period <= 1001 + 40, 1);
  T_MODE(2) = 0;
}

static void test_flags(void) {
  T_COMP(0) = 100;
  T_MODE(0) = 0x0000;
  spin(200);
  uint32_t m = T_MODE(0);
  CHECK_EQ("reached comp", m & 0x0800, 0x0800);
  CHECK_EQ("comp flag cleared by read", T_MODE(0) & 0x0800, 0);
  T_COUNT(0) = 0xFFF0;
  spin(50);
  CHECK_EQ("reached ffff", T_MODE(0) & 0x1000, 0x1000);
  CHECK_EQ("ffff flag cleared by read", T_MODE(0) & 0x1000, 0);
}

static void test_one_shot_and_toggle(void) {
  I_STAT = 0;
  T_COMP(1) = 200;
  T_MODE(1) = 0x0018; /* ZRET | CMP, one-shot, pulse */
  spin(100);
  CHECK_EQ("one-shot first", I_STAT & 0x20, 0x20);
  I_STAT = ~0x20u;
  spin(100);
  CHECK_EQ("one-shot no second", I_STAT & 0x20, 0);

  T_MODE(1) = 0x00D8; /* ZRET | CMP | REPT | toggle */
  CHECK_EQ("toggle intf set after write", T_MODE(1) & 0x0400, 0x0400);
  I_STAT = 0;
  /* COMP = 200 system clocks: an IRQ and a toggle come within a few hundred polls. */
  int n = 0;
  while (!(I_STAT & 0x20) && ++n < 100000) {
  }
  if (n == 100000) TEST_TIMEOUT("the timer 1 IRQ (I_STAT.5)");
  CHECK_EQ("toggle intf 0 after irq", T_MODE(1) & 0x0400, 0);
  I_STAT = ~0x20u;
  n = 0;
  while (!(T_MODE(1) & 0x0400) && ++n < 100000) {
  }
  if (n == 100000) TEST_TIMEOUT("timer 1 mode bit 10 to toggle back to 1");
  CHECK_EQ("no irq on 0->1", I_STAT & 0x20, 0);
  T_MODE(1) = 0;
}

static void test_timer2_sync(void) {
  T_MODE(2) = 0x0001; /* sync mode 0: stop */
  spin(100);
  CHECK_EQ("timer2 stopped", T_COUNT(2), 0);
  T_MODE(2) = 0x0003; /* sync mode 1: free run */
  spin(100);
  CHECK_EQ("timer2 free", T_COUNT(2) > 100, 1);
  T_MODE(2) = 0;
}

int main(void) {
  test_sources();
  test_target_period();
  test_flags();
  test_one_shot_and_toggle();
  test_timer2_sync();
  return test_done("timers_counts");
}
