/* Stores narrower than the register they reach (JaCzekanski's ps1-tests cpu/io-access-bitwidth;
   the expected values are its psx.log, printed by a console, kept in
   tests/data/ps1-tests/cpu-io-access-bitwidth.log). The CPU drives its whole source register onto
   the data bus for SB and SH: memory takes the addressed bytes, but an I/O register takes all of
   its own bits, so SB of 0x12345678 to a 32-bit DMA address writes 0x345678 and to a 16-bit timer
   target 0x5678. Expansion region 2 with no dev-kit board reads all ones. Each register is
   written 0 first, then stored to with SB, SH and SW in turn, as the hardware test does. */
#include "dma_regs.h"
#include "psx/test.h"

#define VALUE 0x12345678u

static volatile uint32_t ram_word;

static void sb(uint32_t addr, uint32_t v) { __asm__ volatile("sb %0, 0(%1)" : : "r"(v), "r"(addr) : "memory"); }
static void sh(uint32_t addr, uint32_t v) { __asm__ volatile("sh %0, 0(%1)" : : "r"(v), "r"(addr) : "memory"); }
static void sw(uint32_t addr, uint32_t v) { __asm__ volatile("sw %0, 0(%1)" : : "r"(v), "r"(addr) : "memory"); }

typedef void (*store_fn)(uint32_t, uint32_t);
static const store_fn stores[3] = {sb, sh, sw};

/* A 32-bit register read back as a word after each of SB, SH and SW: 3 checks. */
static void word_register(const char *name, uint32_t addr, const uint32_t expect[3]) {
  const uint32_t kept = IO32(addr);
  for (int w = 0; w < 3; ++w) {
    IO32(addr) = 0;
    stores[w](addr, VALUE);
    CHECK_EQ(name, IO32(addr), expect[w]);
  }
  IO32(addr) = kept;
}

/* A register read back as a halfword after SB and SH (the log's 16-bit table): 2 checks. */
static void half_register(const char *name, uint32_t addr, uint32_t expect) {
  const uint16_t kept = IO16(addr);
  for (int w = 0; w < 2; ++w) {
    IO16(addr) = 0;
    stores[w](addr, VALUE);
    CHECK_EQ(name, IO16(addr), expect);
  }
  IO16(addr) = kept;
}

static uint32_t interrupts_off(void) {
  uint32_t sr;
  __asm__ volatile("mfc0 %0, $12" : "=r"(sr));
  __asm__ volatile("mtc0 %0, $12\n nop" : : "r"(sr & ~1u));
  return sr;
}

int main(void) {
  const uint32_t sr = interrupts_off(); /* I_MASK takes 0x5678 for a moment */
  static const uint32_t ram[3] = {0x78, 0x5678, 0x12345678};
  word_register("RAM", (uint32_t)&ram_word | 0xA0000000, ram);
  word_register("scratchpad", 0x1F800000, ram);
  static const uint32_t exp2[3] = {0xFFFFFFFF, 0xFFFFFFFF, 0xFFFFFFFF};
  word_register("expansion 2", 0xBF802000, exp2);
  CHECK_EQ("expansion 2 halfword", IO16(0xBF802000), 0xFFFF);
  CHECK_EQ("expansion 2 byte", *(volatile uint8_t *)0xBF802000, 0xFF);
  static const uint32_t madr[3] = {0x345678, 0x345678, 0x345678};
  word_register("D0_MADR", 0xBF801080, madr);
  static const uint32_t dpcr[3] = {0x12345678, 0x12345678, 0x12345678};
  word_register("DPCR", 0xBF8010F0, dpcr);
  static const uint32_t dicr[3] = {0x340038, 0x340038, 0x340038};
  word_register("DICR", 0xBF8010F4, dicr);
  half_register("JOY_MODE", 0xBF801048, 0x38);
  half_register("I_MASK", 0xBF801074, 0x678);
  half_register("T0_TARGET", 0xBF801108, 0x5678);
  half_register("SPUCNT", 0xBF801DAA, 0x5678);
  I_STAT = 0;
  __asm__ volatile("mtc0 %0, $12\n nop" : : "r"(sr));
  return test_done("cpu_io_width");
}
