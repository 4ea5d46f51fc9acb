/* COP0 hardware breakpoints, checked from inside the console (issue 59 item 2).
   Hardware: pcsx-redux's src/mips/tests/cop0/cop0.c, run on a console, arms a write break from
   kernel mode with DCIC CA800000h (bits 31, 30, 27, 25, 23; bit 29 clear), BDA 58h and BDAM
   FFFFFFF0h: SW $0 to 58h is carried out and then taken at the debug vector 80000040h (not the
   general one) with EPC = the store; SB $0 to 59h likewise, writing its byte; SW to 80000058h and to
   the RAM mirror 00200058h neither break (the compare is on the full address) nor fail to store.
   psx-spx "COP0 - Debug Registers" for the rest: bits 23 and 31 are the super-master enables and
   bit 30 the master enable of bits 24-27, so all three arm execution (bit 24, ((PC XOR BPC) AND
   BPCM) = 0) and data breaks (bit 25 with 26/27 for reads/writes, ((addr XOR BDA) AND BDAM) = 0);
   a break sets status bits 0 (any), 1 (BPC), 2 (BDA), 3 (read), 4 (write) and takes ExcCode 09h;
   EPC and Cause.BD are as for any exception (psx-spx "COP0 - Exception Handling"). An execution
   break is taken before its instruction runs; a data break's load delivers its value, as its
   store is made (the hardware test has no load: our reading). Without an enable nothing happens,
   status bits included. */
#include "psx/test.h"

extern volatile uint32_t bp_record[5];
extern uint32_t debug_vector_stub[2], general_vector_stub[2];
#define CAUSE bp_record[0]
#define EPC bp_record[1]
#define DCIC_AT_BREAK bp_record[2]
#define BREAKS bp_record[3]
#define GENERAL bp_record[4]

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
#define BIT29 (1u << 29)
#define ME (1u << 30)
#define TR (1u << 31)
#define ST_ANY 0x01u
#define ST_PC 0x02u
#define ST_DA 0x04u
#define ST_READ 0x08u
#define ST_WRITE 0x10u

static volatile uint32_t watched[2];

/* One break taken at the debug vector (none at the general one): ExcCode 09h (Bp), EPC, Cause.BD
   and DCIC as the handler saw it. 6 checks. */
static void expect_break(const char *name, uint32_t epc, int bd, uint32_t dcic) {
  tty_printf("%s\n", name);
  CHECK_EQ("  debug-vector entries", BREAKS, 1);
  CHECK_EQ("  general-vector entries", GENERAL, 0);
  CHECK_EQ("  ExcCode", (CAUSE >> 2) & 0x1F, 0x09);
  CHECK_EQ("  EPC", EPC, epc);
  CHECK_EQ("  Cause.BD", CAUSE >> 31, bd);
  CHECK_EQ("  DCIC", DCIC_AT_BREAK, dcic);
  BREAKS = 0;
}

/* No exception at either vector. 2 checks. */
static void expect_no_break(const char *name) {
  tty_printf("%s\n", name);
  CHECK_EQ("  debug-vector entries", BREAKS, 0);
  CHECK_EQ("  general-vector entries", GENERAL, 0);
  BREAKS = GENERAL = 0;
}

/* A pointer to a fixed address the compiler cannot see through (it takes 58h for a null-page
   pointer and warns). */
static volatile uint32_t *at(uint32_t address) {
  __asm__("" : "+r"(address));
  return (volatile uint32_t *)address;
}

/* pcsx-redux's hardware-run cases, in its order (cop0.c). */
static void hardware_cases(void) {
  const uint32_t dcic = 0xCA800000;
  const uint32_t hit = dcic | ST_ANY | ST_DA | ST_WRITE;
  volatile uint32_t *low = at(0x58);
  volatile uint32_t *kseg0 = at(0x80000058);
  volatile uint32_t *mirror = at(0x00200058);
  const uint32_t saved = *low;

  *low = 1;
  arm_data(0x58, 0xFFFFFFF0, dcic);
  bp_sw(low, 0);
  read_dcic();
  expect_break("cpu_cop0_basic_write_bp", (uint32_t)bp_sw, 0, hit);
  CHECK_EQ("  the store is carried out", *low, 0);

  *kseg0 = 1;
  arm_data(0x58, 0xFFFFFFF0, dcic);
  bp_sw(kseg0, 0);
  read_dcic();
  expect_no_break("cpu_cop0_kseg_write_bp");
  CHECK_EQ("  the store is carried out", *kseg0, 0);

  *mirror = 1;
  arm_data(0x58, 0xFFFFFFF0, dcic);
  bp_sw(mirror, 0);
  read_dcic();
  expect_no_break("cpu_cop0_upper_memory_write_bp");
  CHECK_EQ("  the store is carried out", *mirror, 0);

  *low = 0x01020304;
  arm_data(0x58, 0xFFFFFFF0, dcic);
  bp_sb((volatile uint8_t *)low + 1, 0);
  read_dcic();
  expect_break("cpu_cop0_unaligned_write_bp", (uint32_t)bp_sb, 0, hit);
  CHECK_EQ("  the byte is carried out", *low, 0x01020004);
  *low = saved;
}

static void exec_breaks(void) {
  const uint32_t on = DE | PCE | ME | TR;
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

  arm_exec((uint32_t)bp_exec_site, 0xFFFFFFFF, DE | PCE | BIT29 | TR);
  bp_exec();
  expect_no_break("bit 29 in place of bit 30 arms nothing");
  CHECK_EQ("  and sets no status", read_dcic() & 0x3F, 0);
  arm_exec((uint32_t)bp_exec_site, 0xFFFFFFFF, PCE | ME | TR);
  bp_exec();
  read_dcic();
  expect_no_break("breakpoint without bit 23 is quiet");
  arm_exec((uint32_t)bp_exec_site, 0xFFFFFFFF, DE | PCE | ME);
  bp_exec();
  expect_no_break("breakpoint without bit 31 is quiet");
  CHECK_EQ("  and sets no status", read_dcic() & 0x3F, 0);
}

static void read_breaks(void) {
  const uint32_t on = DE | DAE | DR | ME | TR;
  watched[0] = 0x11223344;
  arm_data((uint32_t)&watched[0], 0xFFFFFFFF, on);
  CHECK_EQ("the load delivers its value", bp_lw(&watched[0]), 0x11223344);
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

/* SWL at offset n writes bytes 0..n, SWR at offset n bytes n..3 (psx-spx "Unaligned Load/Store");
   the break watches byte 2 of the word. */
static void partial_write_breaks(uint32_t on) {
  const uint32_t hit = on | ST_ANY | ST_DA | ST_WRITE;
  volatile uint8_t *w = (volatile uint8_t *)&watched[0];
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_sb(w + 1, 0);
  expect_no_break("SB to byte 1 misses byte 2");
  bp_sb(w + 2, 0);
  expect_break("SB to byte 2", (uint32_t)bp_sb, 0, hit);
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_sh(w + 2, 0);
  expect_break("SH to bytes 2-3", (uint32_t)bp_sh, 0, hit);
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_sw(w, 0);
  expect_break("SW to the whole word", (uint32_t)bp_sw, 0, hit);
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_swl(w + 1, 0);
  expect_no_break("SWL at offset 1 (bytes 0-1)");
  bp_swl(w + 3, 0);
  expect_break("SWL at offset 3 (bytes 0-3)", (uint32_t)bp_swl, 0, hit);
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_swr(w + 1, 0);
  expect_break("SWR at offset 1 (bytes 1-3)", (uint32_t)bp_swr, 0, hit);
  arm_data((uint32_t)w + 2, 0xFFFFFFFF, on);
  bp_swr(w + 3, 0);
  expect_no_break("SWR at offset 3 (byte 3)");
  read_dcic();
}

static void write_breaks(void) {
  const uint32_t on = DE | DAE | DW | ME | TR;
  const uint32_t hit = on | ST_ANY | ST_DA | ST_WRITE;
  arm_data((uint32_t)&watched[0], 0xFFFFFFFF, on);
  bp_sw(&watched[0], 0xCAFEF00D);
  expect_break("data write breakpoint", (uint32_t)bp_sw, 0, hit);
  CHECK_EQ("  the store is carried out", watched[0], 0xCAFEF00D);
  arm_data((uint32_t)&watched[0], 0xFFFFFFFF, on);
  bp_lw(&watched[0]);
  expect_no_break("a read does not trip a write breakpoint");
  read_dcic();

  partial_write_breaks(on);

  /* BDAM clearing the low bits watches the whole word. */
  arm_data((uint32_t)&watched[0] + 2, 0xFFFFFFFC, on);
  bp_sb(&watched[0], 0x77);
  expect_break("masked write breakpoint, SB to byte 0", (uint32_t)bp_sb, 0, hit);
  CHECK_EQ("  the byte is carried out", watched[0] & 0xFF, 0x77);

  arm_data((uint32_t)&watched[0], 0xFFFFFFFF, DE | DAE | DW | ME);
  bp_sw(&watched[0], 9);
  expect_no_break("write breakpoint without bit 31 is quiet");
  CHECK_EQ("  and sets no status", read_dcic() & 0x3F, 0);
  CHECK_EQ("  and the store happens", watched[0], 9);
}

int main(void) {
  volatile uint32_t *debug_vector = (volatile uint32_t *)0x80000040;
  volatile uint32_t *general_vector = (volatile uint32_t *)0x80000080;
  debug_vector[0] = debug_vector_stub[0];
  debug_vector[1] = debug_vector_stub[1];
  general_vector[0] = general_vector_stub[0];
  general_vector[1] = general_vector_stub[1];

  CHECK_EQ("DCIC bits 6-11 and 16-22 read zero", (arm_exec(0, 0, 0x007F0FC0), read_dcic()), 0);
  hardware_cases();
  exec_breaks();
  read_breaks();
  write_breaks();
  return test_done("cpu_breakpoints");
}
