/* An interrupt taken right after a load: the R3000 lets the load land after the next instruction
   (its load delay), so a kernel that saves the registers at the exception vector must see the
   loaded value, and ReturnFromException must bring that value back, not the register's older one
   (psx-spx "CPU Load/Store Opcodes", "BIOS Interrupt/Exception Handling"). Timer 2 counts the
   system clock with an IRQ every 1500 cycles (SetRCnt flags: bit 12 IRQ on target, bit 0 clear =
   system clock), handled by the kernel's own root counter handler after a program function in
   chain 0 (so the kernel calls into the program while the interrupted code's registers are
   saved); the loop loads 1 and 2 in turn into one register and checks each value, so hundreds
   of interrupts land in a load delay. */
#include "bios_calls.h"
#include "psx/test.h"

static const volatile uint32_t words[2] = {1, 2};

static volatile uint32_t handler_calls;

/* Chain function 1: counts, and returns 0 so the chains go on to the kernel's timer handler. */
static uint32_t count_interrupt(void) {
  ++handler_calls;
  return 0;
}

static uint32_t element[4] = {0, 0, (uint32_t)count_interrupt, 0};

/* Mismatches over `n` load pairs (0 when every loaded value was kept). */
static uint32_t loads(uint32_t n) {
  uint32_t bad = 0;
  __asm__ volatile(
      ".set noreorder\n"
      "1: lw $t0, 0(%[w])\n"
      "   nop\n"
      "   addiu $t1, $t0, -1\n"
      "   sltu $t1, $zero, $t1\n"
      "   addu %[bad], %[bad], $t1\n"
      "   lw $t0, 4(%[w])\n"
      "   nop\n"
      "   addiu $t1, $t0, -2\n"
      "   sltu $t1, $zero, $t1\n"
      "   addu %[bad], %[bad], $t1\n"
      "   addiu %[n], %[n], -1\n"
      "   bnez %[n], 1b\n"
      "   nop\n"
      ".set reorder\n"
      : [bad] "+r"(bad), [n] "+r"(n)
      : [w] "r"(words)
      : "t0", "t1", "memory");
  return bad;
}

int main(void) {
  uint32_t ev = open_event(0xF2000002, 0x0002, 0x2000, 0);
  enable_event(ev);
  enter_critical_section();
  sys_enq_int_rp(0, element);
  set_rcnt(2, 1500, 0x1000);
  start_rcnt(2);
  exit_critical_section();
  uint32_t bad = loads(200000);
  stop_rcnt(2);
  sys_deq_int_rp(0, element);
  CHECK_EQ("timer 2 interrupts were taken", test_event(ev), 1);
  CHECK_EQ("the chain function ran for them", handler_calls > 100, 1);
  CHECK_EQ("no loaded value lost to an interrupt", bad, 0);
  return test_done("bios_irq_load");
}
