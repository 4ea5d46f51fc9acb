/* The HLE kernel's heap (A0h:33h-39h InitHeap/malloc/free/calloc/realloc) and kernel memory
   (B0h:00h/01h). Expected behaviour is the C standard's: distinct non-overlapping blocks, NULL
   when the heap cannot satisfy a request, freed space reusable, calloc zeroed, realloc keeping
   the contents. */
#include "bios_calls.h"
#include "psx/test.h"

static uint8_t heap[4096];

int main(void) {
  bios_init_heap(heap, sizeof heap);
  uint8_t *a = bios_malloc(100), *b = bios_malloc(200), *c = bios_malloc(1);
  CHECK_EQ("malloc a in heap", a >= heap && a + 100 <= heap + sizeof heap, 1);
  CHECK_EQ("malloc b in heap", b >= heap && b + 200 <= heap + sizeof heap, 1);
  CHECK_EQ("malloc c in heap", c >= heap && c + 1 <= heap + sizeof heap, 1);
  CHECK_EQ("a, b disjoint", a + 100 <= b || b + 200 <= a, 1);
  CHECK_EQ("b, c disjoint", b + 200 <= c || c + 1 <= b, 1);
  CHECK_EQ("a, c disjoint", a + 100 <= c || c + 1 <= a, 1);
  CHECK_EQ("aligned", ((uint32_t)a | (uint32_t)b | (uint32_t)c) & 3, 0);
  bios_memset(a, 0xAA, 100);
  bios_memset(b, 0xBB, 200);
  CHECK_EQ("writes to a do not reach b", b[0] == 0xBB && a[99] == 0xAA, 1);

  /* The heap is 4096 bytes: a block of 4096 cannot fit; after freeing everything, a block of
     3000 bytes fits (the freed neighbours merge). */
  CHECK_EQ("too big", (uint32_t)bios_malloc(sizeof heap), 0);
  CHECK_EQ("3000 does not fit beside a, b, c and the first 3000", (uint32_t)bios_malloc(3000) != 0 && (uint32_t)bios_malloc(3000) == 0, 1);
  bios_init_heap(heap, sizeof heap);
  a = bios_malloc(1000);
  b = bios_malloc(1000);
  c = bios_malloc(1000);
  CHECK_EQ("three 1000-byte blocks", a && b && c, 1);
  CHECK_EQ("a fourth does not fit", (uint32_t)bios_malloc(1200), 0);
  bios_free(a);
  bios_free(b);
  uint8_t *big = bios_malloc(1900);
  CHECK_EQ("freed neighbours merge", big != 0 && big + 1900 <= c, 1);
  bios_free(big);
  bios_free(c);

  /* calloc zero-fills; realloc keeps the old contents when it grows. */
  bios_memset(heap, 0x55, sizeof heap);
  bios_init_heap(heap, sizeof heap);
  uint32_t *z = bios_calloc(10, 4);
  int zero = 1;
  for (int i = 0; i < 10; ++i) zero &= z[i] == 0;
  CHECK_EQ("calloc zeroes", zero, 1);
  for (int i = 0; i < 10; ++i) z[i] = 0x1000 + i;
  uint32_t *blocker = bios_malloc(16);
  uint32_t *g = bios_realloc(z, 400);
  int kept = g != 0;
  for (int i = 0; g && i < 10; ++i) kept &= g[i] == 0x1000u + i;
  CHECK_EQ("realloc keeps contents", kept, 1);
  CHECK_EQ("realloc block disjoint from blocker", (uint8_t *)g + 400 <= (uint8_t *)blocker || (uint8_t *)blocker + 16 <= (uint8_t *)g, 1);
  CHECK_EQ("realloc(NULL, n) allocates", bios_realloc(0, 8) != 0, 1);
  CHECK_EQ("malloc(0) returns a block", bios_malloc(0) != 0, 1);

  /* Kernel memory: two blocks, distinct, freed one reused. */
  uint8_t *k1 = alloc_kernel_memory(64), *k2 = alloc_kernel_memory(64);
  CHECK_EQ("kernel memory", k1 && k2 && (k1 + 64 <= k2 || k2 + 64 <= k1), 1);
  free_kernel_memory(k1);
  CHECK_EQ("kernel memory reused", (uint32_t)alloc_kernel_memory(64), (uint32_t)k1);
  return test_done("bios_heap");
}
