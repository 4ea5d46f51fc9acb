/* Arithmetic, logic, shift, multiply and divide instructions from inside the console, with the
   edge cases psx-spx "CPU Arithmetic/Multiply/Divide" documents. Expected values are worked out
   by hand in the comments. */
#include "psx/test.h"

#define ASM3(insn, a, b)                                                 \
  ({                                                                     \
    uint32_t r_;                                                         \
    __asm__ volatile(insn " %0, %1, %2" : "=r"(r_) : "r"(a), "r"(b));    \
    r_;                                                                  \
  })

struct hilo {
  uint32_t hi, lo;
};

/* "div $zero, a, b" is the raw DIV (plain "div a, b" would be the assembler's checking macro). */
#define MULDIV(insn, a, b)                                                                       \
  ({                                                                                             \
    struct hilo r_;                                                                              \
    __asm__ volatile(insn " %2, %3\n\tmfhi %0\n\tmflo %1" : "=r"(r_.hi), "=r"(r_.lo)             \
                     : "r"(a), "r"(b)                                                            \
                     : "hi", "lo");                                                              \
    r_;                                                                                          \
  })

static volatile uint32_t v_m1 = 0xFFFFFFFF, v_min = 0x80000000, v_7 = 7, v_0 = 0, v_3 = 3, v_m7 = 0xFFFFFFF9;

int main(void) {
  CHECK_EQ("ADDU wraps", ASM3("addu", v_m1, v_7), 6);
  CHECK_EQ("SUBU wraps", ASM3("subu", v_0, v_7), 0xFFFFFFF9);
  CHECK_EQ("SLT signed", ASM3("slt", v_m1, v_7), 1);
  CHECK_EQ("SLTU unsigned", ASM3("sltu", v_m1, v_7), 0);
  CHECK_EQ("AND", ASM3("and", v_m7, v_7), 1);
  CHECK_EQ("OR", ASM3("or", v_min, v_7), 0x80000007);
  CHECK_EQ("XOR", ASM3("xor", v_m1, v_7), 0xFFFFFFF8);
  CHECK_EQ("NOR", ASM3("nor", v_min, v_7), 0x7FFFFFF8);
  CHECK_EQ("SRAV keeps the sign", ASM3("srav", v_min, v_3), 0xF0000000);
  CHECK_EQ("SRLV shifts in zeros", ASM3("srlv", v_min, v_3), 0x10000000);
  CHECK_EQ("SLLV uses the low 5 bits", ASM3("sllv", v_7, v_m1 /* 31 */), 0x80000000);

  struct hilo m = MULDIV("mult", v_m1, v_7); /* -1 * 7 = -7 */
  CHECK_EQ("MULT hi", m.hi, 0xFFFFFFFF);
  CHECK_EQ("MULT lo", m.lo, 0xFFFFFFF9);
  m = MULDIV("multu", v_m1, v_7); /* 0xFFFFFFFF * 7 = 0x6_FFFFFFF9 */
  CHECK_EQ("MULTU hi", m.hi, 6);
  CHECK_EQ("MULTU lo", m.lo, 0xFFFFFFF9);
  m = MULDIV("div $zero,", v_m7, v_3); /* -7 / 3 = -2 remainder -1 (truncating) */
  CHECK_EQ("DIV quotient", m.lo, 0xFFFFFFFE);
  CHECK_EQ("DIV remainder", m.hi, 0xFFFFFFFF);
  m = MULDIV("div $zero,", v_7, v_0); /* x/0, x >= 0: lo = -1, hi = x */
  CHECK_EQ("DIV by zero lo", m.lo, 0xFFFFFFFF);
  CHECK_EQ("DIV by zero hi", m.hi, 7);
  m = MULDIV("div $zero,", v_m7, v_0); /* x/0, x < 0: lo = 1, hi = x */
  CHECK_EQ("DIV negative by zero lo", m.lo, 1);
  CHECK_EQ("DIV negative by zero hi", m.hi, 0xFFFFFFF9);
  m = MULDIV("div $zero,", v_min, v_m1); /* 0x80000000 / -1: lo = 0x80000000, hi = 0 */
  CHECK_EQ("DIV INT_MIN/-1 lo", m.lo, 0x80000000);
  CHECK_EQ("DIV INT_MIN/-1 hi", m.hi, 0);
  m = MULDIV("divu $zero,", v_7, v_0); /* x/0 unsigned: lo = 0xFFFFFFFF, hi = x */
  CHECK_EQ("DIVU by zero lo", m.lo, 0xFFFFFFFF);
  CHECK_EQ("DIVU by zero hi", m.hi, 7);
  m = MULDIV("divu $zero,", v_m1, v_7); /* 4294967295 / 7 = 613566756 r 3 */
  CHECK_EQ("DIVU quotient", m.lo, 613566756);
  CHECK_EQ("DIVU remainder", m.hi, 3);
  return test_done("cpu_alu");
}
