/* The state a program finds at its entry point, as the BIOS's Exec() leaves it (psx-spx "BIOS
   Exec Functions", "COP0 - Status Register", "BIOS Memory Map"): sp and fp at the header's stack
   base plus offset (psxexe writes 801FFFF0h + 0), gp from the header (0: -G0 builds), kernel
   mode with the exception vectors in RAM (BEV clear), COP2 usable, the kernel's vectors and
   table of tables in low RAM. crt0 reaches main without touching sp, fp or gp, so main, written
   in assembly below, records them as the entry point had them. */
#include "psx/test.h"

uint32_t entry_regs[4]; /* sp, fp, gp, SR */
int checks_main(void);

__asm__(".set noreorder\n"
        ".globl main\n"
        "main:\n"
        "  la $t0, entry_regs\n"
        "  sw $sp, 0($t0)\n"
        "  sw $fp, 4($t0)\n"
        "  sw $gp, 8($t0)\n"
        "  mfc0 $t1, $12\n"
        "  nop\n"
        "  j checks_main\n"
        "  sw $t1, 12($t0)\n"
        ".set reorder\n");

#define KWORD(a) (*(volatile uint32_t *)(0x80000000u | (a)))

int checks_main(void) {
  CHECK_EQ("sp = stack base + offset", entry_regs[0], 0x801FFFF0);
  CHECK_EQ("fp = sp", entry_regs[1], 0x801FFFF0);
  CHECK_EQ("gp from the header", entry_regs[2], 0);
  CHECK_EQ("SR.KUc kernel mode", entry_regs[3] & 2, 0);
  CHECK_EQ("SR.BEV clear", entry_regs[3] & (1u << 22), 0);
  CHECK_EQ("SR.CU2 set", entry_regs[3] >> 30 & 1, 1);
  CHECK_EQ("table of tables: ExCB pointer in kernel RAM", (KWORD(0x100) & 0x1FFFFFFF) < 0x10000, 1);
  CHECK_EQ("table of tables: EvCB size", KWORD(0x124), 16 * 0x1C);
  CHECK_EQ("RAM size word at 60h (MiB)", KWORD(0x60), 2);
  return test_done("bios_entry");
}
