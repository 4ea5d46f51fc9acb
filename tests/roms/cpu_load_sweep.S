# On-chip port load timing (cpu_load_sweep.c): each routine runs 32 iterations of a load from the
# port at a0 and the instructions after it, unrolled as pcsx-redux's load-timings test has them,
# between two reads of root counter 2 (system clock), twice, and returns the second, cached
# pass's count. s_N: the load and N nops. r_N: the load, N nops, an addiu of the loaded register
# and 7 - N nops (load-timings' intlckN).
        .set noreorder
        .set noat
        .text

#include "counter2_bracket.inc"

        .macro  SPACED name, nops
        TIMED   \name
        .rept   32
        lw      $t0, 0($a0)
        .rept   \nops
        nop
        .endr
        .endr
        DONE
        .endm

        TIMED   t_empty
        DONE

        SPACED  s_0, 0
        SPACED  s_1, 1
        SPACED  s_2, 2
        SPACED  s_3, 3
        SPACED  s_4, 4
        SPACED  s_5, 5
        SPACED  s_6, 6
        SPACED  s_7, 7

        .macro  READER name, before
        TIMED   \name
        .rept   32
        lw      $t0, 0($a0)
        .rept   \before
        nop
        .endr
        addiu   $t0, $t0, 1
        .rept   7 - \before
        nop
        .endr
        .endr
        DONE
        .endm

        READER  r_1, 1
        READER  r_2, 2
        READER  r_3, 3
        READER  r_4, 4
        READER  r_5, 5
        READER  r_6, 6
        READER  r_7, 7
