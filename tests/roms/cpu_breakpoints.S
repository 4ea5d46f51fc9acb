# COP0 hardware breakpoints (psx-spx "COP0 - Debug Registers"): a debug-vector handler that records
# Cause, EPC and DCIC, clears DCIC (the first thing psx-spx says a handler must do) and returns: to
# EPC after an execution break, which is taken before the instruction runs, and to EPC+4 after a
# data break, which is taken after the access (as pcsx-redux's hardware-run handler does); a
# general-vector handler that counts the exceptions that come there instead; plus one routine per
# breakpoint site.
        .set noreorder
        .set noat
        .text

# bp_record: +0 Cause, +4 EPC, +8 DCIC at entry, +12 debug-vector count, +16 general-vector count
        .globl bp_record
        .data
bp_record:
        .word   0, 0, 0, 0, 0
        .text

# Copied to 0x80000040, the debug vector, and to 0x80000080, the general vector.
        .globl debug_vector_stub, general_vector_stub
debug_vector_stub:
        j       debug_handler
        nop
general_vector_stub:
        j       general_handler
        nop

debug_handler:
        mfc0    $k1, $7
        mtc0    $zero, $7
        la      $k0, bp_record
        sw      $k1, 8($k0)
        mfc0    $k1, $13
        nop
        sw      $k1, 0($k0)
        mfc0    $k1, $14
        nop
        sw      $k1, 4($k0)
        lw      $k1, 12($k0)
        nop
        addiu   $k1, $k1, 1
        sw      $k1, 12($k0)
        lw      $k1, 8($k0)
        mfc0    $k0, $14
        andi    $k1, $k1, 0x02      # DCIC bit 1: an execution break, run the instruction now
        bnez    $k1, 1f
        nop
        addiu   $k0, $k0, 4         # a data break: the access is done, go on after it
1:      jr      $k0
        rfe

general_handler:
        la      $k0, bp_record
        lw      $k1, 16($k0)
        nop
        addiu   $k1, $k1, 1
        sw      $k1, 16($k0)
        mfc0    $k0, $14
        nop
        addiu   $k0, $k0, 4
        jr      $k0
        rfe

# void arm_exec(uint32_t bpc, uint32_t bpcm, uint32_t dcic)
        .globl arm_exec
arm_exec:
        mtc0    $a0, $3
        mtc0    $a1, $11
        jr      $ra
        mtc0    $a2, $7

# void arm_data(uint32_t bda, uint32_t bdam, uint32_t dcic)
        .globl arm_data
arm_data:
        mtc0    $a0, $5
        mtc0    $a1, $9
        jr      $ra
        mtc0    $a2, $7

# uint32_t read_dcic(void): also disarms, leaving DCIC zero
        .globl read_dcic
read_dcic:
        mfc0    $v0, $7
        nop
        jr      $ra
        mtc0    $zero, $7

# uint32_t bp_exec(void): returns 1; bp_exec_site is its third instruction, in a 16-byte block.
        .balign 16
        .globl bp_exec, bp_exec_site
bp_exec:
        nop
        nop
bp_exec_site:
        li      $v0, 1
        jr      $ra
        nop

# uint32_t bp_delay(void): returns 2; the li sits in a taken branch's delay slot.
        .globl bp_delay, bp_delay_branch, bp_delay_slot
bp_delay:
bp_delay_branch:
        beq     $zero, $zero, 1f
bp_delay_slot:
        li      $v0, 2
        li      $v0, 3              # skipped by the branch
1:      jr      $ra
        nop

# Each access routine's first instruction is its access.
        .globl bp_lw, bp_lb, bp_sw, bp_sh, bp_sb, bp_swl, bp_swr
bp_lw:  lw      $v0, 0($a0)
        jr      $ra
        nop
bp_lb:  lbu     $v0, 0($a0)
        jr      $ra
        nop
bp_sw:  sw      $a1, 0($a0)
        jr      $ra
        nop
bp_sh:  sh      $a1, 0($a0)
        jr      $ra
        nop
bp_sb:  sb      $a1, 0($a0)
        jr      $ra
        nop
bp_swl: swl     $a1, 0($a0)
        jr      $ra
        nop
bp_swr: swr     $a1, 0($a0)
        jr      $ra
        nop
