# Load timing from cached code (cpu_load_timing.c): each routine runs one sequence of loads from
# RAM (a0 points at three words) between two reads of root counter 2, twice, and returns the
# second, cached pass's count. Timer 2 must count the system clock (mode 0).
        .set noreorder
        .set noat
        .text

#include "counter2_bracket.inc"

# The opening read is followed by four nops: they keep its own bus tail (cpu.h kIoTail, met by a
# load in the next two) out of the sequence, which would otherwise hide it in a first load but
# not in the empty sequence's closing read.
        TIMED   t_empty, 4
        DONE

        TIMED   t_lw_nop, 4
        lw      $t0, 0($a0)
        nop
        DONE

        TIMED   t_lw_lw_nop, 4
        lw      $t0, 0($a0)
        lw      $t1, 4($a0)
        nop
        DONE

        TIMED   t_lw_lw_same_nop, 4
        lw      $t0, 0($a0)
        lw      $t0, 4($a0)
        nop
        DONE

        TIMED   t_lw3_nop, 4
        lw      $t0, 0($a0)
        lw      $t1, 4($a0)
        lw      $t2, 8($a0)
        nop
        DONE

        TIMED   t_lw3_same_nop, 4
        lw      $t0, 0($a0)
        lw      $t0, 4($a0)
        lw      $t0, 8($a0)
        nop
        DONE

        TIMED   t_lw_6nops, 4
        lw      $t0, 0($a0)
        .rept   6
        nop
        .endr
        DONE

        TIMED   t_lw_7nops, 4
        lw      $t0, 0($a0)
        .rept   7
        nop
        .endr
        DONE

        TIMED   t_lw_move, 4
        lw      $t0, 0($a0)
        move    $t4, $t0
        DONE

        TIMED   t_lw_nop_use, 4
        lw      $t0, 0($a0)
        nop
        move    $t4, $t0
        .rept   4
        nop
        .endr
        DONE
