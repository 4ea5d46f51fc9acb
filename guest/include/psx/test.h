/* Minimal test harness for PlayStation test programs: each failed check prints what was expected
   and what was seen; test_done() prints how many checks ran and failed, and returns the failure
   count for main to exit with through the debug port. The counters are defined once, in
   guest/runtime.c, so checks in every file of a program count; the test runner compares the
   printed check count with the count the test declares (tests/roms/CMakeLists.txt), so a program
   that skips checks fails. */
#ifndef PSX_TEST_H
#define PSX_TEST_H
#include "psx/tty.h"

extern int test_failures; /* checks that failed, plus waits that gave up (test_timeout) */
extern int test_checks;   /* CHECK_EQ evaluations */

#define CHECK_EQ(name, actual, expected)                                                        \
  do {                                                                                          \
    uint32_t a_ = (uint32_t)(actual), e_ = (uint32_t)(expected);                                \
    ++test_checks;                                                                              \
    if (a_ != e_) {                                                                             \
      ++test_failures;                                                                          \
      tty_printf("FAIL %s: expected 0x%08x, got 0x%08x (%s:%d)\n", name, e_, a_, __FILE__, __LINE__); \
    }                                                                                           \
  } while (0)

/* A bounded wait that ran out: a failure that names what was awaited (not a check: the count of
   checks stays what the program's code says). */
#define TEST_TIMEOUT(what)                                                                      \
  do {                                                                                          \
    ++test_failures;                                                                            \
    tty_printf("FAIL timed out waiting for %s (%s:%d)\n", what, __FILE__, __LINE__);            \
  } while (0)

static inline int test_done(const char *suite) {
  tty_printf("%s: %d checks, %d failures\n", suite, test_checks, test_failures);
  return test_failures;
}

#endif
