/* Instruction cache timing, measured with root counter 2 on the system clock (one count per CPU
   cycle). psx-spx "Memory Map" (i-Cache): KUSEG/KSEG0 code runs through a direct-mapped cache of
   256 four-word lines tagged with the physical address and per-word valid bits; KSEG1 code is
   never cached; a miss fills from the fetched word to the end of the line, IBLKSZ = 0 stops a
   fill entered at word 0 after two words, and a miss on a word whose line tag matches refills
   the whole line. "Memory Control" (FFFE0130h): IS1 enables the cache; with SR.IsC and TAG a
   store writes the addressed line's tag (address bits from the store address, valid bits from
   the data) and not memory.
   Costs: a cached instruction takes 1 cycle; an uncached one 1 + 4 (the RAM word fetch,
   Bus::kRamFetchUncached); a fill costs that 4 cycles for each word it reads. timed_loop's 16
   instructions fill its four lines: 4 * 4 words * 4 = 64 cycles. Differences between two runs
   cancel the fixed cost of the call and the timer reads. */
#include "psx/test.h"

typedef void (*loop_fn)(uint32_t);
uint32_t time_call(loop_fn fn, uint32_t n);
void timed_loop(uint32_t n);
void write_tags(uint32_t addr, uint32_t lines, uint32_t data);
uint32_t get_bcc(void);
void set_bcc(uint32_t v);

#define KSEG1(f) ((uint32_t)(f) | 0xA0000000u)
#define KUSEG(f) ((uint32_t)(f) & 0x1FFFFFFFu)
#define LOOP ((uint32_t)timed_loop)
#define IS1 (1u << 11)
#define IBLKSZ (3u << 8)

static void tags(uint32_t addr, uint32_t lines, uint32_t data) {
  ((void (*)(uint32_t, uint32_t, uint32_t))KSEG1(write_tags))(addr, lines, data);
}

static uint32_t warm(uint32_t fn, uint32_t n) {
  time_call((loop_fn)fn, n);
  return time_call((loop_fn)fn, n);
}

int main(void) {
  const uint32_t bcc = get_bcc();
  CHECK_EQ("BCC enables the i-cache", bcc & IS1, IS1);

  CHECK_EQ("cached: 10 passes of 16 instructions at 1 cycle", warm(LOOP, 20) - warm(LOOP, 10), 10 * 16 * 1);
  CHECK_EQ("KSEG1: 10 passes at 1 + 4 cycles", warm(KSEG1(LOOP), 20) - warm(KSEG1(LOOP), 10), 10 * 16 * 5);

  const uint32_t hot = warm(LOOP, 10);
  const uint32_t first_word = *(volatile uint32_t *)KSEG1(LOOP);
  tags(LOOP, 4, 0);
  CHECK_EQ("isolated tag stores leave RAM alone", *(volatile uint32_t *)KSEG1(LOOP), first_word);
  /* Valid bits cleared under the loop's own tag: each line is refilled whole (4 words). */
  CHECK_EQ("invalidated lines refill: 16 words * 4", time_call(timed_loop, 10) - hot, 64);
  CHECK_EQ("  then hit again", time_call(timed_loop, 10), hot);

  tags(LOOP, 4, 0);
  tags(LOOP, 4, 0xF);
  CHECK_EQ("tags written valid for the loop's address hit", time_call(timed_loop, 10), hot);
  tags(LOOP + 0x1000, 4, 0xF);
  /* Entered at word 0, each line fills words 0-3 under the new tag. */
  CHECK_EQ("tags of another address 4 KiB away miss", time_call(timed_loop, 10) - hot, 64);
  tags(LOOP, 1, 0x1);
  CHECK_EQ("word 1 invalid under a matching tag: one 4-word refill", time_call(timed_loop, 10) - hot, 16);

  CHECK_EQ("the tag is physical: the KUSEG mirror hits KSEG0's lines", time_call((loop_fn)KUSEG(LOOP), 10), hot);

  set_bcc(bcc & ~IBLKSZ);
  tags(LOOP + 0x1000, 4, 0);
  /* Each line's tag is another address's: entered at word 0 it fills words 0-1 (2 words), then
     word 2 misses under the now matching tag and refills the line (4 words). */
  CHECK_EQ("2-word refill: (2 + 4) words * 4 per line", time_call(timed_loop, 10) - hot, 4 * 6 * 4);
  set_bcc(bcc & ~IS1);
  CHECK_EQ("IS1 clear: KSEG0 runs uncached", warm(LOOP, 20) - warm(LOOP, 10), 10 * 16 * 5);
  set_bcc(bcc);

  return test_done("cpu_icache");
}
