# Timer 2's count read just after a MODE write resets it (timers_reset.c): the store is the last
# word of an i-cache line and the read the first of the next, so that on a first call the
# read's own line misses and is refilled between the two.
        .set noreorder
        .set noat
        .text

        .balign 16
        .globl  t_reset_read
t_reset_read:
        lui     $t0, 0x1F80
        nop
        nop
        sh      $zero, 0x1124($t0)
        lhu     $v0, 0x1120($t0)
        jr      $ra
        nop
