/* Writes a known pattern for the memory-watch tests (tests/unit/console_watch_test.cpp): stores
   of each width, a store of an unchanged value, a store through a mirror and one outside the
   watched range, in this order. Run on its own it reads the stores back (reads raise no watch
   events), so the program fails if a store went missing or landed elsewhere. */
#include <stdint.h>

#include "psx/test.h"

#define U8(a) (*(volatile uint8_t *)(a))
#define U16(a) (*(volatile uint16_t *)(a))
#define U32(a) (*(volatile uint32_t *)(a))

int main(void) {
  U8(0x80100000) = 0x11;
  U16(0x80100002) = 0x2233;
  U32(0x80100004) = 0x44556677;
  U32(0x80100004) = 0x44556677;
  U32(0xA0300008) = 0x8899AABB; /* KSEG1, second 2 MiB mirror: physical 0x00100008 */
  U32(0x80100100) = 0xFFFFFFFF; /* outside the watched 16 bytes */
  CHECK_EQ("byte store", U8(0x80100000), 0x11);
  CHECK_EQ("halfword store", U16(0x80100002), 0x2233);
  CHECK_EQ("word store", U32(0x80100004), 0x44556677);
  CHECK_EQ("store through the KSEG1 mirror at 0x00300008", U32(0x80100008), 0x8899AABB);
  CHECK_EQ("store outside the watched range", U32(0x80100100), 0xFFFFFFFF);
  return test_done("watch_writes");
}
