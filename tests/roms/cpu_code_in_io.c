/* Code executed from memory that is not RAM (issue 59 item 7), after ps1-tests cpu/code-in-io:
   JR $RA; NOP stored at an address and called. On a real console
   (tests/data/ps1-tests/cpu-code-in-io.log) it returns from RAM, from the SPU's voice registers (1F801C00h), from
   DMA channel 0's BCR and CHCR (1F801084h) and from DPCR and DICR (1F8010F0h): those ports read
   back what was stored and the CPU fetches from them. From the scratchpad (1F800000h), the MDEC
   (1F801820h) and the interrupt controller (1F801070h) the call ends in an instruction bus error
   (ExcCode 06h); for the scratchpad, whose first fetch fails, EPC is that address (psx-spx "COP0 -
   Exception Handling": a jump to a faulty address raises the error at the target). The MDEC's and
   the interrupt controller's ports hold other words than those stored (a command, an
   acknowledge), which run until the fetch reaches a port no device answers. */
#include "psx/test.h"

extern volatile uint32_t io_record[3];
extern uint32_t io_vector_stub[2], io_return_code[2];
void call_io(uint32_t address);
#define CAUSE io_record[0]
#define EPC io_record[1]
#define COUNT io_record[2]
#define EXC_IBE 0x06u

static uint32_t ram_code[2];

/* Stores the routine at `address` and calls it. */
static void run_at(uint32_t address) {
  volatile uint32_t *code = (volatile uint32_t *)address;
  code[0] = io_return_code[0];
  code[1] = io_return_code[1];
  call_io(address);
}

static void expect_runs(const char *name, uint32_t address) {
  tty_printf("%s\n", name);
  run_at(address);
  CHECK_EQ("  no exception", COUNT, 0);
  COUNT = 0;
}

static void expect_bus_error(const char *name, uint32_t address) {
  tty_printf("%s\n", name);
  run_at(address);
  CHECK_EQ("  one exception", COUNT, 1);
  CHECK_EQ("  ExcCode", (CAUSE >> 2) & 0x1F, EXC_IBE);
  COUNT = 0;
}

int main(void) {
  volatile uint32_t *vector = (volatile uint32_t *)0x80000080;
  volatile uint32_t *i_mask = (volatile uint32_t *)0x1F801074;
  volatile uint32_t *dpcr = (volatile uint32_t *)0x1F8010F0, *dicr = (volatile uint32_t *)0x1F8010F4;
  vector[0] = io_vector_stub[0];
  vector[1] = io_vector_stub[1];

  expect_runs("testCodeInRam", (uint32_t)ram_code);
  expect_bus_error("testCodeInScratchpad", 0x1F800000);
  CHECK_EQ("  EPC", EPC, 0x1F800000);
  expect_bus_error("testCodeInMDEC", 0x1F801820);
  const uint32_t mask = *i_mask;
  expect_bus_error("testCodeInInterrupts", 0x1F801070);
  *i_mask = mask;
  expect_runs("testCodeInSPU", 0x1F801C00);
  expect_runs("testCodeInDMA0", 0x1F801084);
  const uint32_t dpcr_was = *dpcr, dicr_was = *dicr;
  expect_runs("testCodeInDMAControl", 0x1F8010F0);
  *dpcr = dpcr_was;
  *dicr = dicr_was & 0x00FFFFFF;  /* writing back the flags (bits 24-30) would acknowledge them */
  return test_done("cpu_code_in_io");
}
