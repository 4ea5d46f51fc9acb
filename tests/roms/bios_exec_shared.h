/* What bios_exec and its child program share: scratchpad words (the kernel leaves the scratchpad
   alone, psx-spx "Scratchpad Note", so they survive Load, Exec, LoadExec and _boot) and the
   stack LoadExec is given. */
#ifndef BIOS_EXEC_SHARED_H
#define BIOS_EXEC_SHARED_H
#include <stdint.h>

#define SCRATCH ((volatile uint32_t *)0x1F800000)
enum {
  kPhase = 0,           /* what the programs are doing, below */
  kTableEntry = 1,      /* the A0h table entry 57h the kernel set up */
  kParentChecks = 2,    /* the parent's check and failure counts, for the child to go on with */
  kParentFailures = 3,
  kFileGp = 4,          /* the child EXE header's gp0 */
  kChildA0 = 8,         /* written by the child's entry code (bios_exec_child_start.S) */
  kChildA1 = 9,
  kChildSp = 10,
  kChildGp = 11,
  kChildBss = 12,       /* the child's BSS word as Exec left it */
};
enum { kPhaseBoot = 0x544F4F42, kPhaseExec = 0x43455845, kPhaseLoadExec = 0x58454C44 };
enum { kLoadExecStack = 0x801E0000, kLoadExecOffset = 0x80 };
#endif
