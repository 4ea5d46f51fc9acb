/* Load timing from cached code (the load shadow, src/core/cpu/cpu.h): hardware measurements by
   rustation's author (gist.github.com/simias/a4c3fa560de72e67a5b0b2ce9cf0298c), code running
   from the i-cache and loading from main RAM, in CPU cycles per sequence:
     lw;nop 8 | lw t0;lw t1;nop 14 | lw t0;lw t0;nop 15 | three lw to different registers + nop
     20, to the same register 22 | lw + 6 nops 8, + 7 nops 9 | lw t0; move t4,t0 8 |
     lw t0; nop; move t4,t0; 4 nops 13 (the reader after the delay slot waits for the access).
   (His measuring program, gist add4886436ccabbace1bc6b7a83d9f11, reset timer 1 by a store to its
   counter right before the sequence and read it right after; docs/fidelity.md.)
   Here each sequence is timed with root counter 2 on the system clock (one count per cycle)
   between two timer reads, on a second pass so its code is cached. The fixed cost of the two reads is
   the count of an empty sequence, subtracted from each, so the expected values are the table's.
   The closing read is a memory access: like any, it waits for the last load's access to end, so
   the count covers every load of the sequence, as the measurements do. */
#include "psx/test.h"

#define SEQUENCES(X)            \
  X(t_lw_nop, 8)                \
  X(t_lw_lw_nop, 14)            \
  X(t_lw_lw_same_nop, 15)       \
  X(t_lw3_nop, 20)              \
  X(t_lw3_same_nop, 22)         \
  X(t_lw_6nops, 8)              \
  X(t_lw_7nops, 9)              \
  X(t_lw_move, 8)               \
  X(t_lw_nop_use, 13)

#define DECLARE(name, cycles) uint32_t name(const uint32_t *p);
SEQUENCES(DECLARE)
uint32_t t_empty(const uint32_t *p);

static uint32_t words[3] = {1, 2, 3};

int main(void) {
  *(volatile uint32_t *)0x1F801124 = 0; /* timer 2 mode: system clock, free running */
  const uint32_t empty = t_empty(words);
#define CHECK(name, cycles) CHECK_EQ(#name, name(words) - empty, cycles);
  SEQUENCES(CHECK)
  return test_done("cpu_load_timing");
}
