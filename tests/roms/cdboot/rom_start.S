# Start-up code of the cdboot boot ROM (reset vector 0xBFC00000): memory control, interrupt
# controller, cache control and COP0 set as a BIOS does (psx-spx "Memory Control"), A0h/B0h/C0h
# vectors that just return, then the C runtime: .data copied from ROM to RAM, .bss cleared, a
# stack in the kernel area of RAM, and rom_main(). Also exe_jump(), the hand-over to an EXE.
#include "../rom_init.inc"
        .set noreorder
        .section .text.start, "ax"
        .globl  _start
_start:
        ROM_HW_INIT

        la      $t0, __data_load
        la      $t1, __data_start
        la      $t2, __data_end
1:      beq     $t1, $t2, 2f
        nop
        lw      $t3, 0($t0)
        addiu   $t0, $t0, 4
        sw      $t3, 0($t1)
        b       1b
        addiu   $t1, $t1, 4
2:      la      $t1, __bss_start
        la      $t2, __bss_end
3:      beq     $t1, $t2, 4f
        nop
        sw      $zero, 0($t1)
        b       3b
        addiu   $t1, $t1, 4
4:      la      $sp, __rom_stack_top
        jal     rom_main
        move    $fp, $sp
5:      b       5b
        nop

# void exe_jump(uint32_t pc, uint32_t gp, uint32_t sp): enters a loaded EXE as the BIOS's Exec()
# does, with GP, SP and FP set; a return from it lands in the idle loop above.
        .text
        .globl  exe_jump
exe_jump:
        move    $gp, $a1
        move    $sp, $a2
        move    $fp, $a2
        la      $ra, 5b
        jr      $a0
        nop
