/* Load timing from an on-chip port (issue 59 item 5), as pcsx-redux's src/mips/tests/load-timings
   measured it on a console (hardware-checked asserts of its loadShadow case): 32 loads from
   I_STAT, each followed by s nops, cost 164, 196, 228, 228, 228, 260, 292, 324 cycles for
   s = 0..7. Every figure is 32 times a whole per-load cost plus 4, the cost of the test's bracket
   (two counter reads); here the bracket's cost is the count of an empty sequence, subtracted, so
   each check expects the figure less 4. Its loadInterlocked case, hardware-checked the same
   way: 32 x (the load, then 8 instructions, the 2nd..8th an addiu of the loaded register: r_1
   .. r_7) cost 420, 420, 388, 356, 356, 356, 356, the reader 2nd and 3rd waiting 2 cycles, the
   4th 1. The rule these follow is the comment at CpuT::kIoTail. */
#include "psx/test.h"

#define SEQUENCES(X) \
  X(s_0, 164) X(s_1, 196) X(s_2, 228) X(s_3, 228) X(s_4, 228) X(s_5, 260) X(s_6, 292) X(s_7, 324) \
  X(r_1, 420) X(r_2, 420) X(r_3, 388) X(r_4, 356) X(r_5, 356) X(r_6, 356) X(r_7, 356)

#define DECLARE(name, cycles) uint32_t name(uint32_t port);
SEQUENCES(DECLARE)
uint32_t t_empty(uint32_t port);

#define I_STAT 0xBF801070u /* the port the console test reads */
#define BRACKET 4          /* the console test's two counter reads */

int main(void) {
  *(volatile uint32_t *)0x1F801124 = 0; /* timer 2 mode: system clock, free running */
  const uint32_t empty = t_empty(I_STAT);
#define CHECK(name, cycles) CHECK_EQ(#name, name(I_STAT) - empty, (cycles) - BRACKET);
  SEQUENCES(CHECK)
  return test_done("cpu_load_sweep");
}
