/* An exception that is not an interrupt or SYSCALL, resolved by the program (psx-spx "BIOS
   Interrupt/Exception Handling", "BIOS Function Summary" A(40h) SystemErrorUnresolvedException;
   OpenBIOS src/mips/openbios/handlers/syscall.c, syscallVerifier): the kernel's syscall handler
   delivers F0000010h/1000h, then calls A0h:40h through the A table. A program that replaces
   that entry (as ps1-tests' hookUnresolvedExceptionHandler does) finds Cause and EPC in the
   current thread's TCB, moves EPC past the faulting instruction and returns; the kernel then
   returns from the exception to that EPC with the other registers as they were. */
#include "bios_calls.h"
#include "psx/test.h"

#define KWORD(a) (*(volatile uint32_t *)(0x80000000u | (a)))
/* TCB offsets (psx-spx "BIOS Thread Functions"): EPC at 88h, Cause at 98h. */
#define TCB_EPC 0x88
#define TCB_CAUSE 0x98
#define EXC_ADEL 4

uint32_t misaligned_load(const uint32_t *p);
extern const uint32_t fault_insn[];

/* misaligned_load: s0 = 13579BDFh, then LW from p + 1 (an address error, AdEL); returns s0 as
   it is after the exception, which the kernel must have restored. */
__asm__(".set noreorder\n"
        ".globl misaligned_load\n"
        "misaligned_load:\n"
        "  addiu $sp, $sp, -8\n"
        "  sw $s0, 0($sp)\n"
        "  li $s0, 0x13579BDF\n"
        ".globl fault_insn\n"
        "fault_insn:\n"
        "  lw $t1, 1($a0)\n"
        "  move $v0, $s0\n"
        "  lw $s0, 0($sp)\n"
        "  jr $ra\n"
        "  addiu $sp, $sp, 8\n"
        ".set reorder\n");

static volatile uint32_t order, event_at, handler_at, cause_code, fault_epc;

static void on_unknown_exception(void) { event_at = ++order; }

static void unresolved_exception(void) {
  uint32_t tcb = KWORD(KWORD(0x108)); /* the PCB's current thread */
  handler_at = ++order;
  cause_code = (KWORD(tcb + TCB_CAUSE) >> 2) & 0x1F;
  fault_epc = KWORD(tcb + TCB_EPC);
  KWORD(tcb + TCB_EPC) = fault_epc + 4;
}

int main(void) {
  static const uint32_t words[2] = {0x11111111, 0x22222222};
  volatile uint32_t *a_table = (volatile uint32_t *)0x80000200;

  enter_critical_section();
  uint32_t ev = open_event(0xF0000010, 0x1000, 0x1000, on_unknown_exception);
  enable_event(ev);
  exit_critical_section();
  uint32_t old_entry = a_table[0x40];
  a_table[0x40] = (uint32_t)unresolved_exception;
  uint32_t s0 = misaligned_load(words);
  a_table[0x40] = old_entry;
  close_event(ev);

  CHECK_EQ("F0000010h/1000h delivered first", event_at, 1);
  CHECK_EQ("then A0h:40h called through the A table", handler_at, 2);
  CHECK_EQ("Cause in the TCB: AdEL", cause_code, EXC_ADEL);
  CHECK_EQ("EPC in the TCB: the faulting LW", fault_epc, (uint32_t)fault_insn);
  CHECK_EQ("resumed after it with s0 kept", s0, 0x13579BDF);
  return test_done("bios_exceptions");
}
