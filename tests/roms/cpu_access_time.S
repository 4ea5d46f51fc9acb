# Load cost by region (cpu_access_time.c): each routine runs, between two reads of root counter 2
# (system clock), 100 iterations of the loop JaCzekanski's ps1-tests cpu/access-time times
# (nop; addiu; load; bnez; nop), or the same loop without the load (four instructions), twice, and returns the
# second, cached pass's count. a0 is the address loaded from. t_lwlr is its loop for a 32-bit
# read from an address 2 past a word boundary, which the compiler makes an LWL+LWR pair
# (nop; lwl; addiu; lwr; bnez; nop).
        .set noreorder
        .set noat
        .text

        .macro  TIMED name, load
        .balign 16
        .globl  \name
\name:
        lui     $t8, 0x1F80
        li      $t7, 2
1:      li      $t6, 100
        lhu     $t9, 0x1120($t8)
2:      nop
        addiu   $t6, $t6, -1
        \load
        bnez    $t6, 2b
        nop
        lhu     $v0, 0x1120($t8)
        addiu   $t7, $t7, -1
        bnez    $t7, 1b
        nop
        subu    $v0, $v0, $t9
        jr      $ra
        andi    $v0, $v0, 0xFFFF
        .endm

        .macro  TIMED_PAIR name
        .balign 16
        .globl  \name
\name:
        lui     $t8, 0x1F80
        li      $t7, 2
1:      li      $t6, 100
        lhu     $t9, 0x1120($t8)
2:      nop
        lwl     $a1, 3($a0)
        addiu   $t6, $t6, -1
        lwr     $a1, 0($a0)
        bnez    $t6, 2b
        nop
        lhu     $v0, 0x1120($t8)
        addiu   $t7, $t7, -1
        bnez    $t7, 1b
        nop
        subu    $v0, $v0, $t9
        jr      $ra
        andi    $v0, $v0, 0xFFFF
        .endm

        TIMED   t_none, ""
        TIMED_PAIR t_lwlr
        TIMED   t_lbu, "lbu $a1, 0($a0)"
        TIMED   t_lhu, "lhu $a1, 0($a0)"
        TIMED   t_lw, "lw $a1, 0($a0)"
