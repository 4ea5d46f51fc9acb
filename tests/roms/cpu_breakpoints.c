/* COP0 hardware breakpoints, checked from inside the console against psx-spx "COP0 - Debug
   Registers": DCIC bit 23 (DE) gates bits 24-31, bit 24 (PCE) breaks when ((PC XOR BPC) AND BPCM)
   = 0, bit 25 (DAE) with bit 26/27 (DR/DW) when ((addr XOR BDA) AND BDAM) = 0, bit 29 (KD) arms
   breaks in kernel mode, and bit 31 (TR) jumps to 80000040h with ExcCode 09h; without TR a break
   only sets the status bits: 0 (any), 1 (BPC), 2 (BDA), 3 (read), 4 (write). EPC and Cause.BD
   are as for any exception (psx-spx "COP0 - Exception Handling"). */
#include "psx/test.h"

extern volatile uint32_t bp_record[4];
extern uint32_t debug_vector_stub[2];
#define CAUSE bp_record[0]
#define EPC bp_record[1]
#define DCIC_AT_BREAK bp_record[2]
#define COUNT bp_record[3]

void arm_exec(uint32_t bpc, uint32_t bpcm, uint32_t dcic);
void arm_data(uint32_t bda, uint32_t bdam, uint32_t dcic);
uint32_t read_dcic(void);
uint32_t bp_exec(void), bp_delay(void);
uint32_t bp_lw(volatile void *p), bp_lb(volatile void *p);
void bp_sw(volatile void *p, uint32_t v), bp_sh(volatile void *p, uint32_t v), bp_sb(volatile void *p, uint32_t v);
void bp_swl(volatile void *p, uint32_t v), bp_swr(volatile void *p, uint32_t v);
extern uint32_t bp_exec_site[], bp_delay_branch[], bp_delay_slot[];

#define DE (1u << 23)
#define PCE (1u << 24)
#define DAE (1u << 25)
#define DR (1u << 26)
#define DW (1u << 27)
#define KD (1u << 29)
#define UD (1u << 30)
#define TR (1u << 31)
#define ST_ANY 0x01u
#define ST_PC 0x02u
#define ST_DA 0x04u
#define ST_READ 0x08u
#define ST_WRITE 0x10u

static volatile uint32_t watched[2];

/* One break taken: ExcCode 09h (Bp), EPC, Cause.BD, DCIC as the handler saw it. */
static void expect_break(const char *name, uint32_t epc, int bd, uint32_t dcic) {
  tty_printf("%s\n", name);
  CHECK_EQ("  breaks taken", COUNT, 1);
  CHECK_EQ("  ExcCode", (CAUSE >> 2) & 0x1F, 0x09);
  CHECK_EQ("  EPC", EPC, epc);
  CHECK_EQ("  Cause.BD", CAUSE >> 31, bd);
  CHECK_EQ("  DCIC", DCIC_AT_BREAK, dcic);
  COUNT = 0;
}

static void expect_no_break(const char *name) {
  CHECK_EQ(name, COUNT, 0);
  COUNT = 0;
}

static void exec_breaks(void) {
  const uint32_t on = DE | PCE | KD | TR;
  arm_exec((uint32_t)bp_exec_site, 0xFFFFFFFF, on);
  CHECK_EQ("instruction runs after the break", bp_exec(), 1);
  expect_break("execute breakpoint", (uint32_t)bp_exec_site, 0, on | ST_ANY | ST_PC);

  arm_exec((uint32_t)bp_delay_slot, 0xFFFFFFFF, on);
  CHECK_EQ("delay-slot instruction runs after the break", bp_delay(), 2);
  expect_break("execute breakpoint in a delay slot", (uint32_t)bp_delay_branch, 1, on | ST_ANY | ST_PC);

  /* BPCM clears the low 4 bits: the first instruction run in bp_exec's 16-byte block breaks. */
  arm_exec((uint32_t)bp_exec_site, 0xFFFFFFF0, on);
  bp_exec();
  expect_break("masked execute breakpoint", (uint32_t)bp_exec, 0, on | ST_ANY | ST_PC);

  arm_exec((uint32_t)bp_exec_site, 0xFFFFFFFF, DE | PCE | UD | TR);
  bp_exec();
  expect_no_break("user-mode-only breakpoint is quiet in kernel mode");
  CHECK_EQ("  and sets no status", read_dcic() & 0x3F, 0);
  arm_exec((uint32_t)bp_exec_site, 0xFFFFFFFF, PCE | KD | TR);
  bp_exec();
  expect_no_break("breakpoint without DE is quiet");
  arm_exec((uint32_t)bp_exec_site, 0xFFFFFFFF, DE | PCE | KD);
  bp_exec();
  expect_no_break("breakpoint without TR takes no exception");
  CHECK_EQ("  but sets the status bits", read_dcic(), DE | PCE | KD | ST_ANY | ST_PC);
}

static void read_breaks(void) {
  const uint32_t on = DE | DAE | DR | KD | TR;
  watched[0] = 0x11223344;
  arm_data((uint32_t)&watched[0], 0xFFFFFFFF, on);
  CHECK_EQ("load completes after the break", bp_lw(&watched[0]), 0x11223344);
  expect_break("data read breakpoint", (uint32_t)(void *)bp_lw, 0, on | ST_ANY | ST_DA | ST_READ);

  arm_data((uint32_t)&watched[0] + 3, 0xFFFFFFFF, on);
  CHECK_EQ("byte load", bp_lb((volatile uint8_t *)&watched[0] + 3), 0x11);
  expect_break("byte read breakpoint", (uint32_t)(void *)bp_lb, 0, on | ST_ANY | ST_DA | ST_READ);

  arm_data((uint32_t)&watched[0], 0xFFFFFFFF, on);
  bp_sw(&watched[0], 5);
  expect_no_break("a write does not trip a read breakpoint");
  bp_lw(&watched[1]);
  expect_no_break("a read of another word does not trip it");
  read_dcic();
}

static void write_breaks(void) {
  const uint32_t on = DE | DAE | DW | KD | TR;
  const uint32_t hit = on | ST_ANY | ST_DA | ST_WRITE;
  volatile uint8_t *w = (volatile uint8_t *)&watched[0];
  arm_data((uint32_t)&watched[0], 0xFFFFFFFF, on);
  bp_sw(&watched[0], 0xCAFEF00D);
  expect_break("data write breakpoint", (uint32_t)bp_sw, 0, hit);
  CHECK_EQ("  the store completes after the break", watched[0], 0xCAFEF00D);
  bp_lw(&watched[0]);
  expect_no_break("a read does not trip a write breakpoint");

  /* Watch byte 2 of the word: a write breaks when it covers that byte. */
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_sb(w + 1, 0);
  expect_no_break("SB to byte 1 misses byte 2");
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_sb(w + 2, 0);
  expect_break("SB to byte 2", (uint32_t)bp_sb, 0, hit);
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_sh(w + 2, 0);
  expect_break("SH to bytes 2-3", (uint32_t)bp_sh, 0, hit);
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_sw(w, 0);
  expect_break("SW to the whole word", (uint32_t)bp_sw, 0, hit);
  /* SWL at offset n writes bytes 0..n, SWR at offset n bytes n..3 (psx-spx "Unaligned Load/Store"). */
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_swl(w + 1, 0);
  expect_no_break("SWL at offset 1 (bytes 0-1)");
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_swl(w + 3, 0);
  expect_break("SWL at offset 3 (bytes 0-3)", (uint32_t)bp_swl, 0, hit);
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_swr(w + 1, 0);
  expect_break("SWR at offset 1 (bytes 1-3)", (uint32_t)bp_swr, 0, hit);
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_swr(w + 3, 0);
  expect_no_break("SWR at offset 3 (byte 3)");

  /* BDAM clearing the low bits watches the whole word. */
  arm_data((uint32_t)w + 2, 0xFFFFFFFC, on);
  bp_sb(w, 0x77);
  expect_break("masked write breakpoint, SB to byte 0", (uint32_t)bp_sb, 0, hit);
  CHECK_EQ("  the byte is written after the break", watched[0] & 0xFF, 0x77);

  arm_data((uint32_t)&watched[0], 0xFFFFFFFF, DE | DAE | DW | KD);
  bp_sw(&watched[0], 9);
  expect_no_break("write breakpoint without TR takes no exception");
  CHECK_EQ("  but sets the status bits", read_dcic(), DE | DAE | DW | KD | ST_ANY | ST_DA | ST_WRITE);
  CHECK_EQ("  and the store happens", watched[0], 9);
}

int main(void) {
  volatile uint32_t *vector = (volatile uint32_t *)0x80000040;
  vector[0] = debug_vector_stub[0];
  vector[1] = debug_vector_stub[1];

  CHECK_EQ("DCIC bits 6-11 and 16-22 read zero", (arm_exec(0, 0, 0x007F0FC0), read_dcic()), 0);
  exec_breaks();
  read_breaks();
  write_breaks();
  return test_done("cpu_breakpoints");
}
