# The project's minimal boot ROM (a 512 KiB image, no Sony code): sets up memory control, the
# interrupt controller and COP0 as a BIOS would, announces itself on the dev-kit DUART, and jumps
# to the shell entry 0x80030000, where the emulator side-loads the EXE exactly as it does after
# a real BIOS.
#include "rom_init.inc"
        .set noreorder
        .text
        .globl  _start
_start:
        ROM_HW_INIT

        la      $t3, banner
1:      lbu     $t4, 0($t3)
        addiu   $t3, $t3, 1
        beqz    $t4, 2f
        nop
        b       1b
        sb      $t4, 0x2023($t0)    # DUART channel A transmit
2:      li      $sp, 0x801FFFF0
        move    $fp, $sp
        li      $t5, 0x80030000
        jr      $t5
        nop

banner:
        .asciz  "psxrl boot ROM\n"
