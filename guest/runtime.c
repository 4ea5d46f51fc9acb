/* The few C library and libgcc helpers that GCC may call from PlayStation code, and the counters
   of the test harness (psx/test.h). The Debian cross toolchain's own libraries target MIPS32r2
   with PIC and hardware float, so programs cannot link them. */
#include <stddef.h>
#include <stdint.h>

/* psx/test.h's counters, one pair per program whatever the number of files that check. */
int test_failures;
int test_checks;

void *memcpy(void *dst, const void *src, size_t n) {
  unsigned char *d = dst;
  const unsigned char *s = src;
  while (n--) *d++ = *s++;
  return dst;
}

void *memmove(void *dst, const void *src, size_t n) {
  unsigned char *d = dst;
  const unsigned char *s = src;
  if (d < s) {
    while (n--) *d++ = *s++;
  } else {
    while (n--) d[n] = s[n];
  }
  return dst;
}

void *memset(void *dst, int c, size_t n) {
  unsigned char *d = dst;
  while (n--) *d++ = (unsigned char)c;
  return dst;
}

int memcmp(const void *a, const void *b, size_t n) {
  const unsigned char *x = a, *y = b;
  for (; n; --n, ++x, ++y)
    if (*x != *y) return *x - *y;
  return 0;
}

size_t strlen(const char *s) {
  size_t n = 0;
  while (s[n]) ++n;
  return n;
}

/* 64-bit division by shift-and-subtract: MIPS I has only 32-bit DIV/DIVU. */
static uint64_t udivmod64(uint64_t num, uint64_t den, uint64_t *rem) {
  uint64_t q = 0, r = 0;
  if (den == 0) {
    if (rem) *rem = num;
    return ~(uint64_t)0;
  }
  for (int i = 63; i >= 0; --i) {
    r = (r << 1) | ((num >> i) & 1);
    if (r >= den) {
      r -= den;
      q |= (uint64_t)1 << i;
    }
  }
  if (rem) *rem = r;
  return q;
}

uint64_t __udivdi3(uint64_t a, uint64_t b) { return udivmod64(a, b, 0); }

uint64_t __umoddi3(uint64_t a, uint64_t b) {
  uint64_t r;
  udivmod64(a, b, &r);
  return r;
}

int64_t __divdi3(int64_t a, int64_t b) {
  int neg = (a < 0) != (b < 0);
  uint64_t q = udivmod64(a < 0 ? -(uint64_t)a : (uint64_t)a, b < 0 ? -(uint64_t)b : (uint64_t)b, 0);
  return neg ? -(int64_t)q : (int64_t)q;
}

int64_t __moddi3(int64_t a, int64_t b) {
  uint64_t r;
  udivmod64(a < 0 ? -(uint64_t)a : (uint64_t)a, b < 0 ? -(uint64_t)b : (uint64_t)b, &r);
  return a < 0 ? -(int64_t)r : (int64_t)r;
}
