# Start-up code of the cdboot boot ROM (reset vector 0xBFC00000): memory control, interrupt
# controller, cache control and COP0 set as a BIOS does (psx-spx "Memory Control"), A0h/B0h/C0h
# vectors that just return, then the C runtime: .data copied from ROM to RAM, .bss cleared, a
# stack in the kernel area of RAM, and rom_main(). Also exe_jump(), the hand-over to an EXE.
        .set noreorder
        .section .text.start, "ax"
        .globl  _start
_start:
        lui     $t0, 0x1F80
        li      $t1, 0x1F000000
        sw      $t1, 0x1000($t0)    # expansion 1 base
        li      $t1, 0x1F802000
        sw      $t1, 0x1004($t0)    # expansion 2 base
        li      $t1, 0x0013243F
        sw      $t1, 0x1008($t0)    # expansion 1 delay/size
        li      $t1, 0x00003022
        sw      $t1, 0x100C($t0)    # expansion 3 delay/size
        li      $t1, 0x0013243F
        sw      $t1, 0x1010($t0)    # BIOS ROM delay/size
        li      $t1, 0x200931E1
        sw      $t1, 0x1014($t0)    # SPU delay
        li      $t1, 0x00020843
        sw      $t1, 0x1018($t0)    # CD-ROM delay
        li      $t1, 0x00070777
        sw      $t1, 0x101C($t0)    # expansion 2 delay/size
        li      $t1, 0x00031125
        sw      $t1, 0x1020($t0)    # common delay
        li      $t1, 0x00000B88
        sw      $t1, 0x1060($t0)    # RAM_SIZE: 2 MiB, mirrored over 8 MiB
        sw      $zero, 0x1074($t0)  # I_MASK: nothing enabled (the drive is polled)
        sw      $zero, 0x1070($t0)  # I_STAT: acknowledge everything
        lui     $t2, 0xFFFE
        li      $t1, 0x0001E988
        sw      $t1, 0x0130($t2)    # cache control as the BIOS sets it
        mtc0    $zero, $12          # SR: kernel mode, interrupts off, RAM exception vectors

        # No kernel: each BIOS call vector returns at once ("jr $ra; nop"), so a booted program's
        # BIOS calls return and the emulator's putchar hooks still print.
        li      $t6, 0x03E00008
        sw      $t6, 0x00A0($zero)
        sw      $zero, 0x00A4($zero)
        sw      $t6, 0x00B0($zero)
        sw      $zero, 0x00B4($zero)
        sw      $t6, 0x00C0($zero)
        sw      $zero, 0x00C4($zero)

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
