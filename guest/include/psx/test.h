/* Minimal test harness for PlayStation test programs: each failed check prints what was expected
   and what was seen; test_done() exits through the debug port with the number of failures. */
#ifndef PSX_TEST_H
#define PSX_TEST_H
#include "psx/tty.h"

static int test_failures;
static int test_checks;

#define CHECK_EQ(name, actual, expected)                                                        \
  do {                                                                                          \
    uint32_t a_ = (uint32_t)(actual), e_ = (uint32_t)(expected);                                \
    ++test_checks;                                                                              \
    if (a_ != e_) {                                                                             \
      ++test_failures;                                                                          \
      tty_printf("FAIL %s: expected 0x%08x, got 0x%08x (%s:%d)\n", name, e_, a_, __FILE__, __LINE__); \
    }                                                                                           \
  } while (0)

static inline int test_done(const char *suite) {
  tty_printf("%s: %d checks, %d failures\n", suite, test_checks, test_failures);
  return test_failures;
}

#endif
