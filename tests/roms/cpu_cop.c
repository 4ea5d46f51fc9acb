/* Coprocessor instructions and their exceptions (issue 59 item 7), in kernel mode as ps1-tests
   runs them. The first 17 cases are ps1-tests cpu/cop's, in its order; a real console printed
   "pass" for each (tests/data/ps1-tests/cpu-cop.log): with SR.CUn clear, COP1, MFC2, COP3 and
   SWC0/2/3 raise an exception (COP3's is Coprocessor Unusable), and with CUn set none of them
   does, nor do COP0 and COP2 commands with rs = 1Fh; COP0 works in kernel mode whatever CU0 is.
   The exception code and Cause.CE of the other unusable cases and the last four cases follow
   psx-spx "COP0 - Misc" and "COP0 - Exception Handling". */
#include "psx/test.h"

extern volatile uint32_t cop_record[3];
extern uint32_t cop_vector_stub[2];
#define CAUSE cop_record[0]
#define COUNT cop_record[2]

uint32_t get_sr(void);
void set_sr(uint32_t sr);
typedef uint32_t (*cop_case)(void *buffer);
uint32_t case_mfc0_prid(void *), case_cop0_cmd_1f(void *), case_swc0(void *), case_cop1(void *);
uint32_t case_mfc2(void *), case_cop2_cmd_1f(void *), case_swc2(void *), case_cop3(void *), case_swc3(void *);
uint32_t case_tlbr(void *), case_cfc0(void *), case_bc0f(void *), case_mfc0_r16(void *);

#define NONE 0xFFu
#define EXC_RI 0x0Au
#define EXC_CPU 0x0Bu
#define CU(n) (1u << (28 + (n)))

static uint32_t buffer[2];

/* Runs one case with SR.CUn set or clear (and interrupts off, so that only the case can enter the
   handler), returning what the case leaves in v0. */
static uint32_t run(cop_case c, unsigned cop, int enabled) {
  const uint32_t sr = get_sr();
  set_sr(((enabled ? sr | CU(cop) : sr & ~CU(cop))) & ~1u);
  const uint32_t v = c(buffer);
  set_sr(sr);
  return v;
}

/* One case's outcome: how many exceptions, and for one, its ExcCode and (for Coprocessor
   Unusable) Cause.CE, the coprocessor's number. */
static void expect(const char *name, uint32_t exc, unsigned cop) {
  tty_printf("%s\n", name);
  if (exc == NONE) {
    CHECK_EQ("  no exception", COUNT, 0);
  } else {
    CHECK_EQ("  one exception", COUNT, 1);
    CHECK_EQ("  ExcCode", (CAUSE >> 2) & 0x1F, exc);
    if (exc == EXC_CPU) CHECK_EQ("  Cause.CE", (CAUSE >> 28) & 3, cop);
  }
  COUNT = 0;
}

int main(void) {
  volatile uint32_t *vector = (volatile uint32_t *)0x80000080;
  vector[0] = cop_vector_stub[0];
  vector[1] = cop_vector_stub[1];

  /* ps1-tests cpu/cop, hardware log. */
  CHECK_EQ("MFC0 PRId with CU0 clear reads 2 (psx-spx COP0 - Misc)", run(case_mfc0_prid, 0, 0), 2);
  expect("testCop0Disabled", NONE, 0);
  run(case_mfc0_prid, 0, 1);
  expect("testCop0Enabled", NONE, 0);
  run(case_cop0_cmd_1f, 0, 1);
  expect("testCop0InvalidOpcode", NONE, 0);
  run(case_swc0, 0, 0);
  expect("testSwc0Disabled", EXC_CPU, 0);
  run(case_swc0, 0, 1);
  expect("testSwc0Enabled", NONE, 0);
  run(case_cop1, 1, 0);
  expect("testCop1Disabled", EXC_CPU, 1);
  run(case_cop1, 1, 1);
  expect("testCop1Enabled", NONE, 0);
  run(case_mfc2, 2, 0);
  expect("testCop2Disabled", EXC_CPU, 2);
  run(case_mfc2, 2, 1);
  expect("testCop2Enabled", NONE, 0);
  run(case_cop2_cmd_1f, 2, 1);
  expect("testCop2InvalidOpcode", NONE, 0);
  run(case_swc2, 2, 0);
  expect("testSwc2Disabled", EXC_CPU, 2);
  run(case_swc2, 2, 1);
  expect("testSwc2Enabled", NONE, 0);
  run(case_cop3, 3, 0);
  expect("testCop3Disabled", EXC_CPU, 3);
  run(case_cop3, 3, 1);
  expect("testCop3Enabled", NONE, 0);
  run(case_swc3, 3, 0);
  expect("testSwc3Disabled", EXC_CPU, 3);
  run(case_swc3, 3, 1);
  expect("testSwc3Enabled", NONE, 0);
  run(case_cop3, 3, 0);
  expect("testDisabledCoprocessorThrowsCoprocessorUnusable", EXC_CPU, 3);

  /* psx-spx "COP0 - Misc": the TLB commands and the control registers raise Reserved Instruction,
     BC0F Coprocessor Unusable; cop0r16-r31 read without an exception. */
  run(case_tlbr, 0, 1);
  expect("TLBR", EXC_RI, 0);
  run(case_cfc0, 0, 1);
  expect("CFC0", EXC_RI, 0);
  run(case_bc0f, 0, 1);
  expect("BC0F", EXC_CPU, 0);
  run(case_mfc0_r16, 0, 1);
  expect("MFC0 cop0r16", NONE, 0);
  return test_done("cpu_cop");
}
