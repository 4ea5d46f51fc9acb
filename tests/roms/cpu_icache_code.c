/* What the instruction cache holds (psx-spx "Memory Map", i-Cache): a fill copies the words of a
   line from memory and later hits execute that copy. Stores go to memory only, so code rewritten
   in RAM keeps running in its old form from a KUSEG/KSEG0 address until its line is invalidated
   (tag stores with SR.IsC and BCC.TAG, or the BIOS's FlushCache, A(44h)) or refilled for another
   address 4 KiB away; KSEG1, never cached, always runs what memory holds. Each routine is
   "jr ra; addiu v0, zero, n" and returns n, so the value shows which copy ran. */
#include "bios_calls.h"
#include "psx/test.h"

void write_tags(uint32_t addr, uint32_t lines, uint32_t data);

#define KSEG1(a) ((uint32_t)(a) | 0xA0000000u)
#define JR_RA 0x03E00008u
#define LI_V0(n) (0x24020000u | (n)) /* addiu v0, zero, n */

/* Two routine slots 4 KiB apart: the same cache line, different tags. */
static volatile uint32_t area[1024 + 4] __attribute__((aligned(16)));
#define SLOT ((uint32_t)&area[0])
#define OTHER ((uint32_t)&area[1024])

static void put(uint32_t addr, uint32_t n) {
  ((volatile uint32_t *)addr)[0] = JR_RA;
  ((volatile uint32_t *)addr)[1] = LI_V0(n);
}

static uint32_t call(uint32_t addr) { return ((uint32_t(*)(void))addr)(); }

int main(void) {
  put(SLOT, 7);
  CHECK_EQ("code written to RAM runs", call(SLOT), 7);
  put(SLOT, 9);
  CHECK_EQ("rewritten without a flush: the cached copy runs", call(SLOT), 7);
  CHECK_EQ("KSEG1 runs what memory holds", call(KSEG1(SLOT)), 9);
  CHECK_EQ("  and leaves the cached copy alone", call(SLOT), 7);

  /* Storing 0 over the line's tag under isolation, as FlushCache does; run uncached. */
  ((void (*)(uint32_t, uint32_t, uint32_t))KSEG1(write_tags))(SLOT, 1, 0);
  CHECK_EQ("after a tag store invalidates the line the new code runs", call(SLOT), 9);

  put(SLOT, 5);
  CHECK_EQ("rewritten again: the refilled copy runs", call(SLOT), 9);
  bios_flush_cache();
  CHECK_EQ("after FlushCache the new code runs", call(SLOT), 5);

  put(SLOT, 3);
  put(OTHER, 1);
  CHECK_EQ("code 4 KiB away runs, taking over the line", call(OTHER), 1);
  CHECK_EQ("the evicted code is refilled from memory", call(SLOT), 3);
  return test_done("cpu_icache_code");
}
