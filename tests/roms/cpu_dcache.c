/* The scratchpad in data-cache mode (psx-spx "Memory Control", FFFE0130h with RAM (bit 3) clear
   and DS (bit 7) set): it has no tags, so every load from a cached segment (KUSEG/KSEG0) misses
   and copies the whole word containing the loaded address into scratchpad slot (addr >> 2) & FFh;
   KSEG1 loads bypass it, stores never fill it, and no load ever hits. The scratchpad's own
   addresses hang the bus in that mode, so each check reads it back after restoring BCC. */
#include "psx/test.h"

void dcache_lw(const volatile uint32_t *p, uint32_t count);
void dcache_lbu(const volatile uint32_t *p, uint32_t count);
void dcache_sw(volatile uint32_t *p, uint32_t count);
uint32_t dcache_reload(volatile uint32_t *p, volatile uint32_t *uncached_p, uint32_t v);

#define SCRATCH ((volatile uint32_t *)0x1F800000)
#define KSEG1(p) ((volatile uint32_t *)((uint32_t)(p) | 0xA0000000))
#define POISON 0xEEEEEEEEu

static uint32_t block[512] __attribute__((aligned(1024))); /* two 1 KiB blocks */

static void poison(void) {
  for (int i = 0; i < 256; ++i) SCRATCH[i] = POISON;
}

static uint32_t slots_equal(uint32_t first, uint32_t count, const uint32_t *want) {
  uint32_t bad = 0;
  for (uint32_t i = 0; i < count; ++i) bad += SCRATCH[first + i] != (want ? want[i] : POISON);
  return bad;
}

int main(void) {
  for (int i = 0; i < 512; ++i) block[i] = 0x5A000000u + (uint32_t)i * 0x10001u;

  poison();
  dcache_lw(block, 256);
  CHECK_EQ("LW of a 1 KiB block fills every slot with its word", slots_equal(0, 256, block), 0);

  poison();
  dcache_lw(block + 256 + 2, 3); /* second block: offsets 0x408.. -> slots 2..4 */
  CHECK_EQ("slot is (address >> 2) & FFh", slots_equal(2, 3, block + 258), 0);
  CHECK_EQ("  other slots untouched", slots_equal(5, 251, 0) + slots_equal(0, 2, 0), 0);

  poison();
  dcache_lbu(block, 16);
  CHECK_EQ("LBU fills the whole word", slots_equal(0, 16, block), 0);
  CHECK_EQ("  and only the loaded words", slots_equal(16, 240, 0), 0);

  poison();
  dcache_lw(KSEG1(block), 256);
  CHECK_EQ("KSEG1 loads bypass the data cache", slots_equal(0, 256, 0), 0);

  poison();
  dcache_sw(block + 256, 64);
  CHECK_EQ("stores do not fill the scratchpad", slots_equal(0, 256, 0), 0);
  CHECK_EQ("  but reach RAM", block[256], 64);

  block[7] = 1;
  CHECK_EQ("no load hits: the second load sees RAM's new value",
           dcache_reload(&block[7], KSEG1(&block[7]), 0x77777777), 0x77777777);
  CHECK_EQ("  and its slot holds it", SCRATCH[7], 0x77777777);

  return test_done("cpu_dcache");
}
