/* A MODE write resets the counter: read right after it, the count is below 10, even when the read
   is the first instruction of an i-cache line that misses (pcsx-redux src/mips/tests/timers,
   timerModeWriteResetsCounter, hardware verified). The refill stalls the pipeline while the
   store still waits in the write queue, so the timer is reset after it, not before. Timer 2 on
   the system clock first counts well past 10, so each check could fail. */
#include "dma_regs.h"
#include "psx/test.h"

uint32_t t_reset_read(void);

static void spin(int n) {
  for (volatile int i = 0; i < n; ++i) {
  }
}

/* The count itself where it is 10 or more, so that a failure shows it; 1 where below 10. */
static uint32_t below_10(uint32_t count) { return count < 10 ? 1 : count; }

static void count_up(const char *what) {
  T_COMP(2) = 0xFFFF;
  T_MODE(2) = 0;
  spin(500);
  CHECK_EQ(what, T_COUNT(2) >= 10, 1);
}

int main(void) {
  count_up("counting before the C read");
  T_MODE(2) = 0;
  CHECK_EQ("read after a MODE write", below_10(T_COUNT(2)), 1);
  count_up("counting before the first call");
  CHECK_EQ("read on a new line, refilled", below_10(t_reset_read()), 1);
  count_up("counting before the second call");
  CHECK_EQ("read on a new line, cached", below_10(t_reset_read()), 1);
  return test_done("timers_reset");
}
