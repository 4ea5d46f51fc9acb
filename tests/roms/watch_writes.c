/* Writes a known pattern for the memory-watch tests (tests/unit/console_watch_test.cpp): stores
   of each width, a store of an unchanged value, a store through a mirror and one outside the
   watched range, in this order. */
#include <stdint.h>

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
  return 0;
}
