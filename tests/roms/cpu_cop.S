# Coprocessor instructions and the exceptions they raise (issue 59 item 7): a general-vector
# handler that counts exceptions, records Cause and resumes after the instruction (no case sits in
# a delay slot), SR access, and one routine per case whose first instruction is the case. The
# instructions the assembler has no name for, or names only for other CPUs, are spelled as words.
        .set noreorder
        .set noat
        .text

# cop_record: +0 Cause, +4 EPC, +8 count
        .globl cop_record
        .data
cop_record:
        .word   0, 0, 0
        .text

# Copied to 0x80000080, the general exception vector.
        .globl cop_vector_stub
cop_vector_stub:
        j       cop_handler
        nop

cop_handler:
        la      $k0, cop_record
        mfc0    $k1, $13
        nop
        sw      $k1, 0($k0)
        mfc0    $k1, $14
        nop
        sw      $k1, 4($k0)
        lw      $k1, 8($k0)
        nop
        addiu   $k1, $k1, 1
        sw      $k1, 8($k0)
        mfc0    $k0, $14
        nop
        addiu   $k0, $k0, 4
        jr      $k0
        rfe

# uint32_t get_sr(void), void set_sr(uint32_t)
        .globl get_sr, set_sr
get_sr:
        mfc0    $v0, $12
        jr      $ra
        nop
set_sr:
        mtc0    $a0, $12
        nop
        jr      $ra
        nop

# Each case: uint32_t case(void *buffer); v0 is what the case leaves there (only MFC0/MFC2 set it).
        .macro  CASE name, word
        .globl  \name
\name:
        .word   \word
        nop                         # a load's delay slot
        jr      $ra
        nop
        .endm

        CASE    case_mfc0_prid, 0x40027800      # MFC0 $v0, cop0r15 (PRId)
        CASE    case_cop0_cmd_1f, 0x43E00000    # COP0 command 0 with rs = 1Fh (ps1-tests' "invalid")
        CASE    case_swc0, 0xE0810000           # SWC0 $1, 0($a0)
        CASE    case_cop1, 0x44000000           # COP1, all other bits zero (MFC1 $0, $f0)
        CASE    case_mfc2, 0x48020800           # MFC2 $v0, GTE data register 1
        CASE    case_cop2_cmd_1f, 0x4BE00000    # COP2 with rs = 1Fh: a GTE command 0
        CASE    case_swc2, 0xE8810000           # SWC2 $1, 0($a0)
        CASE    case_cop3, 0x4C000000           # COP3, all other bits zero
        CASE    case_swc3, 0xEC810000           # SWC3 $1, 0($a0)
        CASE    case_tlbr, 0x42000001           # COP0 command 01h, TLBR
        CASE    case_cfc0, 0x40420000           # CFC0 $v0, cop0 control register 0
        CASE    case_bc0f, 0x41000000           # BC0F +0
        CASE    case_mfc0_r16, 0x40028000       # MFC0 $v0, cop0r16
