# Instruction cache timing (psx-spx "Memory Map", i-Cache; "Memory Control", FFFE0130h): a loop
# of exactly four cache lines, timed with root counter 2 on the system clock, and a routine that
# writes i-cache tags the way the BIOS's FlushCache does (SR.IsC with BCC.TAG and IS1).
        .set noreorder
        .text

# uint32_t time_call(void (*fn)(uint32_t), uint32_t n): cycles from before to after fn(n).
        .globl  time_call
time_call:
        addiu   $sp, $sp, -8
        sw      $ra, 4($sp)
        lui     $t8, 0x1F80
        sw      $zero, 0x1124($t8)  # timer 2 mode 0: system clock, counter reset to 0
        lhu     $t9, 0x1120($t8)
        nop                         # the counter read's bus tail (cpu.h kIoTail), which a
        nop                         # fetch from memory in the next 4 instructions would meet,
        nop                         # passes here, so that the call's fixed cost does not depend
        nop                         # on the called code's first lines hitting the cache
        jalr    $a0
        move    $a0, $a1
        lhu     $v0, 0x1120($t8)
        nop
        subu    $v0, $v0, $t9
        andi    $v0, $v0, 0xFFFF
        lw      $ra, 4($sp)
        addiu   $sp, $sp, 8
        jr      $ra
        nop

# void timed_loop(uint32_t n): n passes over 16 instructions, cache lines 0-3 of the routine.
        .balign 16
        .globl  timed_loop
timed_loop:
1:      addiu   $a0, $a0, -1
        .rept   13
        nop
        .endr
        bnez    $a0, 1b
        nop
        jr      $ra                 # line 4: outside the timed lines
        nop

# void write_tags(uint32_t addr, uint32_t lines, uint32_t data): stores data at addr, addr+16...
# with the cache isolated and BCC = TAG | IS1, writing those lines' tags. Call it uncached.
        .globl  write_tags
write_tags:
        lui     $t8, 0xFFFE
        lw      $t9, 0x130($t8)
        li      $t0, 0x804          # TAG (bit 2) | IS1 (bit 11)
        sw      $t0, 0x130($t8)
        mfc0    $t1, $12
        lui     $t2, 0x1            # SR bit 16: IsC
        or      $t2, $t1, $t2
        mtc0    $t2, $12
        nop
1:      sw      $a2, 0($a0)
        addiu   $a1, $a1, -1
        bnez    $a1, 1b
        addiu   $a0, $a0, 16
        mtc0    $t1, $12
        nop
        sw      $t9, 0x130($t8)
        jr      $ra
        nop

        .globl  get_bcc, set_bcc
get_bcc:
        lui     $t8, 0xFFFE
        lw      $v0, 0x130($t8)
        jr      $ra
        nop
set_bcc:
        lui     $t8, 0xFFFE
        sw      $a0, 0x130($t8)
        jr      $ra
        nop
