/* Load cost by region and width, as JaCzekanski's ps1-tests cpu/access-time measured on a console
   (its psx.log, kept in tests/data/ps1-tests/cpu-access-time.log): the cycles one load adds to a
   loop that runs it 100 times, from cached code, timed by root counter 2 on the system clock.
   The log prints the count over 100 as whole cycles and hundredths (e.g. 10.99, 25.99 for
   expansion 2; its format, "%2d.%2-d", prints hundredths below 10 as one digit: 3.8 is 3.08); the expected figures are those rounded to whole cycles, and each measured count is
   rounded the same way. The external regions' times follow their Memory Control Delay/Size
   settings (src/core/memory_control.h). The 32-bit SPU row is read at 1F801DAAh, 2 past a word
   boundary, which the program's compiler makes an LWL+LWR pair (t_lwlr). Left out: main RAM (the
   console: about 5 cycles, which the load-shadow model does not give in this loop). */
#include "psx/test.h"

uint32_t t_none(uint32_t addr);
uint32_t t_lbu(uint32_t addr);
uint32_t t_lhu(uint32_t addr);
uint32_t t_lw(uint32_t addr);
uint32_t t_lwlr(uint32_t addr);

#define NONE 0 /* no such row in the log */

struct row {
  const char *name;
  uint32_t addr;
  uint32_t cycles[3]; /* 8, 16, 32-bit */
};

static const struct row rows[] = {
    {"BIOS", 0xBFC00000, {7, 13, 25}},       /* 7.6, 12.94, 24.94 */
    {"SCRATCHPAD", 0x1F800000, {1, 1, 1}},   /* 1.5, 1.1, 0.94 */
    {"EXPANSION1", 0x1F000000, {7, 13, 25}}, /* 6.94, 13.7, 25.7 */
    {"EXPANSION2", 0x1F802000, {11, 26, 56}},
    {"EXPANSION3", 0x1FA00000, {6, 6, 10}},  /* 6.7, 6.1, 9.95 */
    {"DMAC_CTRL", 0x1F8010F0, {3, 3, 3}},
    {"JOY_STAT", 0x1F801044, {3, 3, 3}},
    {"SIO_STAT", 0x1F801054, {3, 3, 3}},     /* 3.02, 3.02, 2.92 */
    {"RAM_SIZE", 0x1F801060, {3, 3, 3}},     /* 3.04, 3.04, 3.18 */
    {"I_STAT", 0x1F801070, {3, 3, 3}},
    {"TIMER0_VAL", 0x1F801100, {3, 3, 3}},
    {"CDROM_STAT", 0x1F801800, {8, 14, 26}}, /* 8.0, 14.0, 25.93 */
    {"GPUSTAT", 0x1F801814, {3, 3, 3}},      /* 2.93, 2.92, 3.8 */
    {"MDECSTAT", 0x1F801824, {3, 3, 3}},     /* 3.8, 3.8, 3.1 */
    {"SPUCNT", 0x1F801DAA, {18, 18, 39}},    /* 17.99, 17.99, 38.94 */
    {"CACHECTRL", 0xFFFE0130, {1, 1, 1}},    /* 0.95, 1.9, 1.9 */
};

typedef uint32_t (*timed_fn)(uint32_t);
static const timed_fn loads[3] = {t_lbu, t_lhu, t_lw};
static const timed_fn unaligned_word = t_lwlr;

int main(void) {
  *(volatile uint32_t *)0x1F801124 = 0; /* timer 2 mode: system clock, free running */
  const uint32_t empty = t_none(0x1F800000);
  for (unsigned r = 0; r < sizeof rows / sizeof rows[0]; ++r) {
    for (int w = 0; w < 3; ++w) {
      if (rows[r].cycles[w] == NONE) continue;
      const timed_fn load = w == 2 && (rows[r].addr & 3) ? unaligned_word : loads[w];
      const uint32_t added = load(rows[r].addr) - empty;
      CHECK_EQ(rows[r].name, (added + 50) / 100, rows[r].cycles[w]);
    }
  }
  return test_done("cpu_access_time");
}
