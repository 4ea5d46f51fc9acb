/* CPU-bound workload for the interpreter benchmark: a bitwise CRC-32 over a RAM buffer, then
   a sieve of Eratosthenes, repeated; loads, stores, shifts, branches and ALU work in a typical mix. */
#include <stdint.h>

#include "psx/tty.h"

static uint8_t buffer[16384];
static uint8_t sieve[8192];

static uint32_t crc32(const uint8_t *p, uint32_t n) {
  uint32_t crc = 0xFFFFFFFF;
  for (uint32_t i = 0; i < n; ++i) {
    crc ^= p[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320 & -(crc & 1));
  }
  return ~crc;
}

static uint32_t primes(void) {
  uint32_t count = 0;
  for (uint32_t i = 0; i < sizeof sieve; ++i) sieve[i] = 1;
  for (uint32_t i = 2; i < sizeof sieve; ++i) {
    if (!sieve[i]) continue;
    ++count;
    for (uint32_t j = i * 2; j < sizeof sieve; j += i) sieve[j] = 0;
  }
  return count;
}

int main(void) {
  for (uint32_t i = 0; i < sizeof buffer; ++i) buffer[i] = (uint8_t)(i * 31 + 7);
  uint32_t acc = 0;
  for (;;) acc += crc32(buffer, sizeof buffer) + primes();
  return (int)acc;
}
