/* Exceptions and RFE, checked from inside the console: each trigger makes one exception, the
   handler (cpu_exceptions.S) records Cause/EPC/BadVaddr/SR; the expected values are the ones
   psx-spx "COP0 - Exception Handling" documents. */
#include "psx/test.h"

extern volatile uint32_t exc_record[6];
extern uint32_t vector_stub[2];
#define CAUSE exc_record[0]
#define EPC exc_record[1]
#define BADVADDR exc_record[2]
#define SR_AT_ENTRY exc_record[3]
#define COUNT exc_record[4]

#define DECLARE(trigger, site) \
  uint32_t trigger(void *arg);  \
  extern uint32_t site[];
DECLARE(trigger_syscall, syscall_site)
DECLARE(trigger_break, break_site)
DECLARE(trigger_overflow, overflow_site)
DECLARE(trigger_load_misaligned, load_misaligned_site)
DECLARE(trigger_store_misaligned, store_misaligned_site)
DECLARE(trigger_bus_error, bus_error_site)
DECLARE(trigger_reserved, reserved_site)
DECLARE(trigger_cop1, cop1_site)
DECLARE(trigger_fetch_misaligned, fetch_misaligned_resume)
DECLARE(trigger_in_delay_slot, delay_slot_branch)
DECLARE(trigger_soft_interrupt, soft_interrupt_site)
void trigger_masked_interrupt(void);
uint32_t rfe_result(void);

static uint32_t scratch[4];

static void install_handler(void) {
  volatile uint32_t *vector = (volatile uint32_t *)0x80000080;
  vector[0] = vector_stub[0];
  vector[1] = vector_stub[1];
}

static uint32_t code(void) { return (CAUSE >> 2) & 0x1F; }

static void expect(const char *name, uint32_t exc_code, uint32_t epc, int bd) {
  tty_printf("%s\n", name);
  CHECK_EQ("  exception count", COUNT, 1);
  CHECK_EQ("  ExcCode", code(), exc_code);
  CHECK_EQ("  EPC", EPC, epc);
  CHECK_EQ("  Cause.BD", CAUSE >> 31, bd);
  /* On entry the KU/IE stack was pushed: current interrupt enable and kernel mode are 0. */
  CHECK_EQ("  SR.KUc/IEc cleared", SR_AT_ENTRY & 3, 0);
  COUNT = 0;
}

int main(void) {
  install_handler();

  trigger_syscall(0);
  expect("syscall", 0x08, (uint32_t)syscall_site, 0);
  trigger_break(0);
  expect("break", 0x09, (uint32_t)break_site, 0);
  CHECK_EQ("overflow leaves the destination unwritten", trigger_overflow(0), 0x5555);
  expect("overflow", 0x0C, (uint32_t)overflow_site, 0);
  trigger_load_misaligned(scratch);
  expect("load address error", 0x04, (uint32_t)load_misaligned_site, 0);
  CHECK_EQ("  BadVaddr", BADVADDR, (uint32_t)scratch + 1);
  trigger_store_misaligned(scratch);
  expect("store address error", 0x05, (uint32_t)store_misaligned_site, 0);
  CHECK_EQ("  BadVaddr", BADVADDR, (uint32_t)scratch + 1);
  trigger_bus_error(0);
  expect("data bus error", 0x07, (uint32_t)bus_error_site, 0);
  trigger_reserved(0);
  expect("reserved instruction", 0x0A, (uint32_t)reserved_site, 0);
  trigger_cop1(0);
  expect("coprocessor 1 unusable", 0x0B, (uint32_t)cop1_site, 0);
  CHECK_EQ("  Cause.CE", (CAUSE >> 28) & 3, 1);
  trigger_fetch_misaligned(0);
  expect("fetch address error", 0x04, (uint32_t)fetch_misaligned_resume + 2, 0);
  CHECK_EQ("  BadVaddr", BADVADDR, (uint32_t)fetch_misaligned_resume + 2);
  trigger_in_delay_slot(0);
  expect("syscall in a branch delay slot", 0x08, (uint32_t)delay_slot_branch, 1);

  trigger_soft_interrupt(0);
  tty_printf("software interrupt\n");
  CHECK_EQ("  exception count", COUNT, 1);
  CHECK_EQ("  ExcCode", code(), 0);
  CHECK_EQ("  Cause.IP0 pending", (CAUSE >> 8) & 1, 1);
  /* Taken once SR enables it: EPC is one of the two nops after the MTC0. */
  CHECK_EQ("  EPC after the MTC0", EPC == (uint32_t)soft_interrupt_site + 4 || EPC == (uint32_t)soft_interrupt_site + 8, 1);
  COUNT = 0;
  trigger_masked_interrupt();
  CHECK_EQ("masked software interrupt is not taken", COUNT, 0);

  /* SR low bits 110000 (KUo IEo) -> RFE -> 111100 (old kept, previous = old, current = previous) */
  CHECK_EQ("RFE pops the mode stack", rfe_result(), 0x3C);
  return test_done("cpu_exceptions");
}
