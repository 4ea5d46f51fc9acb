/* bios_exec's child program (CHILD.EXE on its disc, linked at 0x80100000). Started by Exec it
   reports what it saw in the scratchpad (its entry code stored a0, a1, sp and gp; here its BSS
   word, which Exec must have cleared) and returns to Exec. Started by LoadExec it finishes the
   test: the parent's check counts come through the scratchpad, and it checks the registers
   LoadExec gave it (psx-spx "LoadExec": Exec(headerbuf, 1, 0) with the stack values passed to
   LoadExec) and that its BSS was cleared again, then exits with the failure count. */
#include "bios_exec_shared.h"
#include "psx/test.h"

static uint32_t bss_word;

uint32_t child_main(uint32_t a0, uint32_t a1) {
  (void)a0, (void)a1;
  if (SCRATCH[kPhase] == kPhaseExec) {
    SCRATCH[kChildBss] = bss_word;
    bss_word = 0x5A5A5A5A;
    return 0x77;
  }
  test_checks = (int)SCRATCH[kParentChecks];
  test_failures = (int)SCRATCH[kParentFailures];
  CHECK_EQ("LoadExec: a0 = 1", SCRATCH[kChildA0], 1);
  CHECK_EQ("LoadExec: a1 = 0", SCRATCH[kChildA1], 0);
  CHECK_EQ("LoadExec: sp = stackbase + stackoffset", SCRATCH[kChildSp], kLoadExecStack + kLoadExecOffset);
  CHECK_EQ("LoadExec: gp from the EXE header", SCRATCH[kChildGp], SCRATCH[kFileGp]);
  CHECK_EQ("LoadExec: BSS cleared again", bss_word, 0);
  psx_exit((uint16_t)test_done("bios_exec"));
  return 0;
}
