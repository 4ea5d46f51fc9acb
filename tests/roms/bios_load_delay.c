/* Entering the kernel with a load in flight (psx-spx "CPU Load/Store Opcodes": the load delay;
   "BIOS Function Summary", "BIOS Interrupt/Exception Handling"). A load lands after the next
   instruction, which here is the kernel's first: the value reaches the register before the kernel reads it, and an
   interrupt taken in a load's delay slot returns with the loaded value in place (the kernel
   saves and restores the registers after the load landed). SetRCnt/StartRCnt/StopRCnt take the
   root counter's event class (F200000xh, "RCntCNTx") as the SDKs pass it and use its low 16
   bits (OpenBIOS src/mips/openbios/handlers/irq.c: initTimer, enableTimerIRQ). */
#include "bios_calls.h"
#include "psx/test.h"

int32_t abs_loaded(const int32_t *p);
uint32_t load_loop(const uint32_t *p, uint32_t expected, uint32_t count);

/* abs_loaded: A0h:0Eh abs() with its argument loaded in the delay slot of the jump to A0h.
   load_loop: count times, s0 = 0, s0 = *p, one instruction (the load's delay slot, where an
   interrupt may be taken with the load pending), then s0 compared with expected; returns the
   number of mismatches. s0 is callee-saved, as the kernel must keep it across an interrupt. */
__asm__(".set noreorder\n"
        ".globl abs_loaded\n"
        "abs_loaded:\n"
        "  li $t2, 0xA0\n"
        "  li $t1, 0x0E\n"
        "  jr $t2\n"
        "  lw $a0, 0($a0)\n"
        ".globl load_loop\n"
        "load_loop:\n"
        "  addiu $sp, $sp, -8\n"
        "  sw $s0, 0($sp)\n"
        "  move $v0, $zero\n"
        "1:\n"
        "  move $s0, $zero\n"
        "  lw $s0, 0($a0)\n"
        "  nop\n"
        "  beq $s0, $a1, 2f\n"
        "  addiu $a2, $a2, -1\n"
        "  addiu $v0, $v0, 1\n"
        "2:\n"
        "  bnez $a2, 1b\n"
        "  nop\n"
        "  lw $s0, 0($sp)\n"
        "  jr $ra\n"
        "  addiu $sp, $sp, 8\n"
        ".set reorder\n");

static volatile uint32_t ticks;
static void on_tick(void) { ++ticks; }

#define RCNT_CNT2 0xF2000002u
#define RCNT_MODE_INTR 0x1000u

int main(void) {
  static const int32_t minus_seven = -7;
  CHECK_EQ("A0h call sees a0 loaded in the jump's delay slot", abs_loaded(&minus_seven), 7);

  /* Root counter 2 interrupts every 1500-1507 cycles (system clock, reset at the target) while
     the loop runs, so the interrupts meet the loop at every phase; the kernel's handler delivers
     F2000002h/0002h and acknowledges it. */
  enter_critical_section();
  uint32_t ev = open_event(RCNT_CNT2, 0x0002, 0x1000, on_tick);
  enable_event(ev);
  CHECK_EQ("SetRCnt(RCntCNT2)", set_rcnt(RCNT_CNT2, 1500, RCNT_MODE_INTR), 1);
  CHECK_EQ("StartRCnt(RCntCNT2)", start_rcnt(RCNT_CNT2), 1);
  exit_critical_section();

  static const uint32_t value = 0x5A5AC3C3;
  uint32_t lost = load_loop(&value, value, 25000);
  for (uint32_t target = 1501; target < 1508; ++target) {
    set_rcnt(RCNT_CNT2, target, RCNT_MODE_INTR);
    lost += load_loop(&value, value, 25000);
  }
  CHECK_EQ("no load lost to an interrupt", lost, 0);
  CHECK_EQ("StopRCnt(RCntCNT2)", stop_rcnt(RCNT_CNT2), 1);
  /* 8 x 25000 iterations of at least 6 cycles each span over 1,200,000 cycles: 790 periods. */
  CHECK_EQ("the counter interrupted the loop", ticks >= 790, 1);
  close_event(ev);
  return test_done("bios_load_delay");
}
