# Scratchpad as a data cache (psx-spx "Memory Control", FFFE0130h "D-cache" mode, RAM=0 DS=1).
# Each routine switches BCC to that mode, makes only the accesses under test (no stack, no other
# loads, since every cached load fills the scratchpad in this mode), then restores BCC.
        .set noreorder
        .text

        .macro  DCACHE_ON
        lui     $t8, 0xFFFE
        lw      $t9, 0x130($t8)     # saved BCC (KSEG2: not cached, fills nothing)
        nop
        li      $t7, ~0x08          # RAM (bit 3) off
        and     $t7, $t9, $t7
        ori     $t7, $t7, 0x80      # DS (bit 7) on
        sw      $t7, 0x130($t8)
        .endm

        .macro  DCACHE_OFF
        sw      $t9, 0x130($t8)
        .endm

# void dcache_lw(const volatile uint32_t *p, uint32_t count): LW count words from p
        .globl  dcache_lw
dcache_lw:
        DCACHE_ON
1:      lw      $t0, 0($a0)
        addiu   $a1, $a1, -1
        bnez    $a1, 1b
        addiu   $a0, $a0, 4
        DCACHE_OFF
        jr      $ra
        nop

# void dcache_lbu(const volatile uint32_t *p, uint32_t count): LBU byte 1 of count words
        .globl  dcache_lbu
dcache_lbu:
        DCACHE_ON
1:      lbu     $t0, 1($a0)
        addiu   $a1, $a1, -1
        bnez    $a1, 1b
        addiu   $a0, $a0, 4
        DCACHE_OFF
        jr      $ra
        nop

# void dcache_sw(volatile uint32_t *p, uint32_t count): SW count words to p
        .globl  dcache_sw
dcache_sw:
        DCACHE_ON
1:      sw      $a1, 0($a0)
        addiu   $a1, $a1, -1
        bnez    $a1, 1b
        addiu   $a0, $a0, 4
        DCACHE_OFF
        jr      $ra
        nop

# uint32_t dcache_reload(volatile uint32_t *p, volatile uint32_t *uncached_p, uint32_t v):
# loads *p, writes v through the uncached mirror, loads *p again and returns the second value.
        .globl  dcache_reload
dcache_reload:
        DCACHE_ON
        lw      $t0, 0($a0)
        sw      $a2, 0($a1)
        lw      $v0, 0($a0)
        DCACHE_OFF
        jr      $ra
        nop
