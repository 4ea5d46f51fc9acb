/* Memory map checks (psx-spx "Memory Map"): RAM mirrors through KUSEG/KSEG0/KSEG1 and the first
   8 MiB, scratchpad in KSEG0 only, access widths and sign extension, the interrupt controller's
   acknowledge rule, the memory-control registers, cache isolation and self-written code. */
#include "psx/test.h"

void store_isolated(volatile uint32_t *p, uint32_t value);
uint32_t copy_and_call(void *dst, const void *src, uint32_t count);
extern uint32_t code_returns_7[2], code_returns_9[2];

#define U32(a) (*(volatile uint32_t *)(a))
#define U16(a) (*(volatile uint16_t *)(a))
#define S16(a) (*(volatile int16_t *)(a))
#define U8(a) (*(volatile uint8_t *)(a))
#define S8(a) (*(volatile int8_t *)(a))

static uint32_t code_area[4];

int main(void) {
  /* RAM mirrors */
  U32(0x80100000) = 0x11223344;
  CHECK_EQ("KSEG1 mirror", U32(0xA0100000), 0x11223344);
  CHECK_EQ("KUSEG mirror", U32(0x00100000), 0x11223344);
  CHECK_EQ("2 MiB mirror 1", U32(0x80300000), 0x11223344);
  CHECK_EQ("2 MiB mirror 3", U32(0x80700000), 0x11223344);
  U32(0xA0500000) = 0x55667788; /* mirror 2 written through KSEG1 */
  CHECK_EQ("write through a mirror", U32(0x80100000), 0x55667788);

  /* widths: little-endian composition and sign extension */
  U32(0x80100010) = 0x8081F0F1;
  CHECK_EQ("LBU byte 0", U8(0x80100010), 0xF1);
  CHECK_EQ("LB sign-extends", (uint32_t)(int32_t)S8(0x80100013), 0xFFFFFF80);
  CHECK_EQ("LHU half 1", U16(0x80100012), 0x8081);
  CHECK_EQ("LH sign-extends", (uint32_t)(int32_t)S16(0x80100010), 0xFFFFF0F1);
  U8(0x80100011) = 0x5A;
  U16(0x80100012) = 0x1234;
  CHECK_EQ("SB/SH merge into the word", U32(0x80100010), 0x12345AF1);

  /* scratchpad: 1 KiB at 0x1F800000 through KUSEG and KSEG0 */
  U32(0x1F800000) = 0xDEADBEEF;
  U32(0x1F8003FC) = 0x0BADF00D;
  CHECK_EQ("scratchpad via KSEG0", U32(0x9F800000), 0xDEADBEEF);
  CHECK_EQ("scratchpad last word", U32(0x9F8003FC), 0x0BADF00D);
  CHECK_EQ("scratchpad is not RAM", U32(0x80000000) == 0xDEADBEEF && U32(0x80000004) == 0x0BADF00D, 0);

  /* expansion region 1 with nothing attached reads all ones */
  CHECK_EQ("expansion 1 open bus", U32(0x1F000000), 0xFFFFFFFF);

  /* interrupt controller: I_MASK keeps 11 bits; writing I_STAT can only clear bits */
  U32(0x1F801074) = 0xFFFFFFFF;
  CHECK_EQ("I_MASK width", U32(0x1F801074), 0x7FF);
  U32(0x1F801074) = 0;
  U32(0x1F801070) = 0xFFFFFFFF;
  CHECK_EQ("I_STAT writes of 1 set nothing", U32(0x1F801070) & ~1u, 0);

  /* memory control: RAM_SIZE and the expansion base registers read back */
  CHECK_EQ("RAM_SIZE default", U32(0x1F801060), 0x00000B88);
  CHECK_EQ("expansion 1 base", U32(0x1F801000), 0x1F000000);

  /* cache isolation */
  U32(0x80100020) = 0xAAAA5555;
  store_isolated((volatile uint32_t *)0x80100020, 0x12121212);
  CHECK_EQ("isolated store does not reach RAM", U32(0x80100020), 0xAAAA5555);

  /* code copied then executed runs; copied over without a cache flush, the old code still runs
     from the i-cache, as stores do not reach it (psx-spx i-Cache; cpu_icache_code has more) */
  CHECK_EQ("first copied routine", copy_and_call(code_area, code_returns_7, 2), 7);
  CHECK_EQ("re-copied routine without a flush runs the cached copy", copy_and_call(code_area, code_returns_9, 2), 7);
  return test_done("cpu_memory");
}
