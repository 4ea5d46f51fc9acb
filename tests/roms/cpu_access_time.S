# Load cost by region (cpu_access_time.c): each routine runs, between two reads of root counter 2
# (system clock), 100 iterations of the loop JaCzekanski's ps1-tests cpu/access-time times
# (nop; addiu; load; bnez; nop), or the same loop without the load (four instructions), twice, and returns the
# second, cached pass's count. a0 is the address loaded from. t_lwlr is its loop for a 32-bit
# read from an address 2 past a word boundary, which the compiler makes an LWL+LWR pair
# (nop; lwl; addiu; lwr; bnez; nop).
        .set noreorder
        .set noat
        .text

#include "counter2_bracket.inc"

# The access-time loop, 100 times a pass: nop, `before`, addiu, `after`, bnez, nop.
        .macro  LOOP name, before, after
        COUNTED \name
1:      li      $t6, 100
        lhu     $t9, 0x1120($t8)
2:      nop
        \before
        addiu   $t6, $t6, -1
        \after
        bnez    $t6, 2b
        nop
        DONE
        .endm

        LOOP    t_none, "", ""
        LOOP    t_lwlr, "lwl $a1, 3($a0)", "lwr $a1, 0($a0)"
        LOOP    t_lbu, "", "lbu $a1, 0($a0)"
        LOOP    t_lhu, "", "lhu $a1, 0($a0)"
        LOOP    t_lw, "", "lw $a1, 0($a0)"
