# Cache isolation (SR.IsC): with the cache isolated, stores go to the cache and not to RAM; this
# is how the BIOS flushes the instruction cache (psx-spx "Cache Control").
        .set noreorder
        .text
        .globl  store_isolated
# void store_isolated(uint32_t *p, uint32_t value)
store_isolated:
        mfc0    $t0, $12
        lui     $t1, 0x1            # SR bit 16: IsC
        or      $t1, $t0, $t1
        mtc0    $t1, $12
        nop
        sw      $a1, 0($a0)
        mtc0    $t0, $12
        nop
        jr      $ra
        nop

# Copies `count` words of code to `dst` and calls it: code written then executed must run.
        .globl  copy_and_call
copy_and_call:
        addiu   $sp, $sp, -8
        sw      $ra, 4($sp)
        move    $t2, $a0
1:      lw      $t3, 0($a1)
        addiu   $a2, $a2, -1
        sw      $t3, 0($t2)
        addiu   $a1, $a1, 4
        bnez    $a2, 1b
        addiu   $t2, $t2, 4
        jalr    $a0
        nop
        lw      $ra, 4($sp)
        addiu   $sp, $sp, 8
        jr      $ra
        nop

        .globl  code_returns_7, code_returns_9
code_returns_7:
        jr      $ra
        li      $v0, 7
code_returns_9:
        jr      $ra
        li      $v0, 9
