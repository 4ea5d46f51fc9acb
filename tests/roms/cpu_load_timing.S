# Load timing from cached code (cpu_load_timing.c): each routine runs one sequence of loads from
# RAM (a0 points at three words) between two reads of root counter 2, twice, and returns the
# second, cached pass's count. Timer 2 must count the system clock (mode 0).
        .set noreorder
        .set noat
        .text

        .macro  TIMED name
        .balign 16
        .globl  \name
\name:
        lui     $t8, 0x1F80
        li      $t7, 2
1:      lhu     $t9, 0x1120($t8)
        nop                     # four instructions keep the counter read's own bus tail (cpu.h
        nop                     # kIoTail, met by a load in the next two) out of the sequence,
        nop                     # which would otherwise hide it in a first load but not in the
        nop                     # empty sequence's closing read
        .endm

        .macro  DONE
        lhu     $v0, 0x1120($t8)
        addiu   $t7, $t7, -1
        bnez    $t7, 1b
        nop
        subu    $v0, $v0, $t9
        jr      $ra
        andi    $v0, $v0, 0xFFFF
        .endm

        TIMED   t_empty
        DONE

        TIMED   t_lw_nop
        lw      $t0, 0($a0)
        nop
        DONE

        TIMED   t_lw_lw_nop
        lw      $t0, 0($a0)
        lw      $t1, 4($a0)
        nop
        DONE

        TIMED   t_lw_lw_same_nop
        lw      $t0, 0($a0)
        lw      $t0, 4($a0)
        nop
        DONE

        TIMED   t_lw3_nop
        lw      $t0, 0($a0)
        lw      $t1, 4($a0)
        lw      $t2, 8($a0)
        nop
        DONE

        TIMED   t_lw3_same_nop
        lw      $t0, 0($a0)
        lw      $t0, 4($a0)
        lw      $t0, 8($a0)
        nop
        DONE

        TIMED   t_lw_6nops
        lw      $t0, 0($a0)
        .rept   6
        nop
        .endr
        DONE

        TIMED   t_lw_7nops
        lw      $t0, 0($a0)
        .rept   7
        nop
        .endr
        DONE

        TIMED   t_lw_move
        lw      $t0, 0($a0)
        move    $t4, $t0
        DONE

        TIMED   t_lw_nop_use
        lw      $t0, 0($a0)
        nop
        move    $t4, $t0
        .rept   4
        nop
        .endr
        DONE
