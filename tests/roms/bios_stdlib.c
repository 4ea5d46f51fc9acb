/* qsort, lsearch, bsearch, atof and strtod (psx-spx "BIOS Misc Functions", "BIOS Number
   Functions"). qsort(base, nel, width, cmp) sorts through a width-byte block on the heap (so
   InitHeap comes first); lsearch/bsearch(key, base, nel, width, cmp) return the element that
   compares equal to the key, or 0; cmp gets two element pointers (the key first for the
   searches) and returns <0, 0 or >0. atof/strtod are compiled for the absent COP1: their first
   COP1 instruction raises a Coprocessor Unusable exception (Cause code 0Bh, CE = 1) in the
   kernel's code, which reaches A(40h) SystemErrorUnresolvedException; the test's A(40h) returns
   to the caller instead of hanging. Expected orders are the arithmetic of the arrays below. */
#include "bios_calls.h"
#include "bios_stdlib_calls.h"
#include "psx/test.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))
#define KWORD(a) (*(volatile uint32_t *)(0x80000000u | (a)))
/* TCB offsets (psx-spx "BIOS Thread Functions"): r31 at 84h, EPC at 88h, Cause at 98h. */
#define TCB_RA 0x84
#define TCB_EPC 0x88
#define TCB_CAUSE 0x98

static uint8_t heap[4096] __attribute__((aligned(8)));
static volatile uint32_t calls, vblanks;

struct record {
  int32_t key;
  uint32_t tag; /* key * 3 + 1: stays with its key */
  uint32_t spare;
};

static int ascending(const void *a, const void *b) {
  ++calls;
  return *(const int32_t *)a - *(const int32_t *)b;
}

static int descending(const void *a, const void *b) { return ascending(b, a); }

/* A comparison slow enough that VBlank interrupts fall between comparisons. */
static int slow_ascending(const void *a, const void *b) {
  for (volatile int k = 0; k < 300; ++k) {
  }
  return ascending(a, b);
}

static void on_vblank(void) { ++vblanks; }

/* Elements out of ascending order (0 when sorted). */
static uint32_t unsorted(const int32_t *v, uint32_t n) {
  uint32_t bad = 0;
  for (uint32_t k = 1; k < n; ++k) bad += v[k - 1] > v[k];
  return bad;
}

static void sorting(void) {
  int32_t v[10] = {5, 3, 9, 1, 7, 0, 8, 2, 6, 4};
  bios_qsort(v, COUNT(v), 4, ascending);
  uint32_t bad = 0;
  for (uint32_t k = 0; k < COUNT(v); ++k) bad += v[k] != (int32_t)k;
  CHECK_EQ("qsort: 0..9 in order", bad, 0);
  bios_qsort(v, COUNT(v), 4, descending);
  bad = 0;
  for (uint32_t k = 0; k < COUNT(v); ++k) bad += v[k] != 9 - (int32_t)k;
  CHECK_EQ("qsort with a descending comparison: 9..0", bad, 0);

  struct record r[7];
  static const int32_t keys[7] = {40, -7, 13, 0, 99, -50, 21};
  for (uint32_t k = 0; k < COUNT(r); ++k) r[k] = (struct record){keys[k], (uint32_t)keys[k] * 3 + 1, 0xABCD};
  bios_qsort(r, COUNT(r), sizeof r[0], ascending);
  static const int32_t sorted_keys[7] = {-50, -7, 0, 13, 21, 40, 99};
  bad = 0;
  for (uint32_t k = 0; k < COUNT(r); ++k)
    bad += r[k].key != sorted_keys[k] || r[k].tag != (uint32_t)r[k].key * 3 + 1 || r[k].spare != 0xABCD;
  CHECK_EQ("qsort of 12-byte records: keys in order, each record whole", bad, 0);

  calls = 0;
  bios_qsort(v, 1, 4, ascending);
  bios_qsort(v, 0, 4, ascending);
  CHECK_EQ("qsort of 0 or 1 elements compares nothing", calls, 0);
}

/* 200 pseudo-random keys (a 32-bit LCG's high half) sorted while VBlank interrupts come. */
static void sorting_under_interrupts(void) {
  static int32_t v[200];
  uint32_t x = 12345, sum = 0, sorted_sum = 0;
  for (uint32_t k = 0; k < COUNT(v); ++k) {
    x = x * 1103515245u + 12345u;
    v[k] = (int32_t)(x >> 16 & 0x7FFF);
    sum += (uint32_t)v[k];
  }
  enter_critical_section();
  uint32_t ev = open_event(0xF2000003, 0x0002, 0x1000, on_vblank);
  enable_event(ev);
  I_MASK = 1;
  exit_critical_section();
  bios_qsort(v, COUNT(v), 4, slow_ascending);
  I_MASK = 0;
  close_event(ev);
  for (uint32_t k = 0; k < COUNT(v); ++k) sorted_sum += (uint32_t)v[k];
  CHECK_EQ("200 keys in order", unsorted(v, COUNT(v)), 0);
  CHECK_EQ("the same keys (sum)", sorted_sum, sum);
  CHECK_EQ("VBlanks came during the sort", vblanks > 0, 1);
}

static void searching(void) {
  static const int32_t unsorted_v[6] = {8, -3, 15, 4, 4, 42};
  int32_t key = 4;
  CHECK_EQ("lsearch: the first 4, element 3", bios_lsearch(&key, unsorted_v, 6, 4, ascending), &unsorted_v[3]);
  key = 42;
  CHECK_EQ("lsearch: the last element", bios_lsearch(&key, unsorted_v, 6, 4, ascending), &unsorted_v[5]);
  key = 7;
  CHECK_EQ("lsearch: no 7", bios_lsearch(&key, unsorted_v, 6, 4, ascending), 0);
  calls = 0;
  bios_lsearch(&key, unsorted_v, 6, 4, ascending);
  CHECK_EQ("lsearch compares each element once", calls, 6);

  static int32_t odd[16];
  for (uint32_t k = 0; k < COUNT(odd); ++k) odd[k] = 2 * (int32_t)k + 1; /* 1, 3, ..., 31 */
  uint32_t found = 0;
  for (int32_t k = 1; k <= 31; k += 2) {
    key = k;
    found += bios_bsearch(&key, odd, COUNT(odd), 4, ascending) == &odd[(k - 1) / 2];
  }
  CHECK_EQ("bsearch: each of the 16 keys at its place", found, 16);
  key = 1;
  CHECK_EQ("bsearch: the first element", bios_bsearch(&key, odd, 16, 4, ascending), &odd[0]);
  key = 31;
  CHECK_EQ("bsearch: the last element", bios_bsearch(&key, odd, 16, 4, ascending), &odd[15]);
  key = 19;
  CHECK_EQ("bsearch: 19 is element 9", bios_bsearch(&key, odd, 16, 4, ascending), &odd[9]);
  uint32_t missing = 0;
  for (int32_t k = 0; k <= 32; k += 2) {
    key = k;
    missing += bios_bsearch(&key, odd, COUNT(odd), 4, ascending) == 0;
  }
  CHECK_EQ("bsearch: none of the 17 even keys 0..32", missing, 17);
  key = 5;
  calls = 0;
  bios_bsearch(&key, odd, 16, 4, ascending);
  CHECK_EQ("bsearch skips elements: fewer comparisons than 16", calls < 16, 1);
  CHECK_EQ("bsearch of 0 elements", bios_bsearch(&key, odd, 0, 4, ascending), 0);
}

static volatile uint32_t unresolved, cause, epc;

static void unresolved_exception(void) {
  uint32_t tcb = KWORD(KWORD(0x108)); /* the PCB's current thread */
  ++unresolved;
  cause = KWORD(tcb + TCB_CAUSE);
  epc = KWORD(tcb + TCB_EPC);
  KWORD(tcb + TCB_EPC) = KWORD(tcb + TCB_RA); /* back to the caller instead of the BIOS's hang */
}

/* Four checks for each of atof and strtod. */
static void faults_on_cop1(int strtod) {
  volatile uint32_t *a_table = (volatile uint32_t *)0x80000200;
  uint32_t old_entry = a_table[0x40];
  unresolved = 0;
  a_table[0x40] = (uint32_t)unresolved_exception;
  if (strtod)
    bios_strtod("1.5", 0);
  else
    bios_atof("1.5");
  a_table[0x40] = old_entry;
  CHECK_EQ("A(40h) SystemErrorUnresolvedException reached once", unresolved, 1);
  CHECK_EQ("Cause: Coprocessor Unusable (0Bh)", (cause >> 2) & 0x1F, 0x0B);
  CHECK_EQ("Cause CE: coprocessor 1", (cause >> 28) & 3, 1);
  CHECK_EQ("EPC in the kernel's RAM (0-FFFFh)", epc >= 0x80000000 && epc < 0x80010000, 1);
}

int main(void) {
  bios_init_heap(heap, sizeof heap);
  sorting();
  sorting_under_interrupts();
  searching();
  faults_on_cop1(0);
  faults_on_cop1(1);
  return test_done("bios_stdlib");
}
