# Exception tests: a handler that records Cause/EPC/BadVaddr/SR and resumes at a continuation the
# trigger routine sets, plus one trigger routine per exception type. psx-spx "COP0 - Exception
# Handling" gives the expected ExcCode, EPC, BD and BadVaddr for each.
        .set noreorder
        .set noat
        .text

# exc_record: +0 Cause, +4 EPC, +8 BadVaddr, +12 SR at entry, +16 count, +20 resume address
        .globl exc_record
        .data
exc_record:
        .word   0, 0, 0, 0, 0, 0
        .text

# Copied to 0x80000080 by install_handler (two instructions: the vector has little room).
        .globl vector_stub
vector_stub:
        j       exc_handler
        nop

exc_handler:
        la      $k0, exc_record
        mfc0    $k1, $13
        nop
        sw      $k1, 0($k0)
        mfc0    $k1, $14
        nop
        sw      $k1, 4($k0)
        mfc0    $k1, $8
        nop
        sw      $k1, 8($k0)
        mfc0    $k1, $12
        nop
        sw      $k1, 12($k0)
        lw      $k1, 16($k0)
        nop
        addiu   $k1, $k1, 1
        sw      $k1, 16($k0)
        mtc0    $zero, $13          # drop software interrupt requests
        lw      $k0, 20($k0)
        nop
        jr      $k0
        rfe

        .macro  TRIGGER name, site
        .globl  \name
        .globl  \site
\name:
        la      $t0, exc_record
        la      $t1, 9f
        sw      $t1, 20($t0)
        .endm

        TRIGGER trigger_syscall, syscall_site
syscall_site:
        syscall
9:      jr      $ra
        nop

        TRIGGER trigger_break, break_site
break_site:
        break   0x123
9:      jr      $ra
        nop

        TRIGGER trigger_overflow, overflow_site
        lui     $t2, 0x7FFF
        ori     $t2, $t2, 0xFFFF
        li      $v0, 0x5555
overflow_site:
        add     $v0, $t2, $t2       # overflows: $v0 must keep 0x5555
9:      jr      $ra
        nop

        TRIGGER trigger_load_misaligned, load_misaligned_site
        move    $t2, $a0
load_misaligned_site:
        lw      $v0, 1($t2)
9:      jr      $ra
        nop

        TRIGGER trigger_store_misaligned, store_misaligned_site
        move    $t2, $a0
store_misaligned_site:
        sh      $zero, 1($t2)
9:      jr      $ra
        nop

        TRIGGER trigger_bus_error, bus_error_site
        lui     $t2, 0x1000         # physical 0x10000000: nothing answers there
bus_error_site:
        lw      $v0, 0($t2)
9:      jr      $ra
        nop

        TRIGGER trigger_reserved, reserved_site
reserved_site:
        .word   0xFC000000          # primary opcode 0x3F does not exist
9:      jr      $ra
        nop

        TRIGGER trigger_cop1, cop1_site
cop1_site:
        .word   0x44020000          # MFC1 $v0, $f0: COP1 does not exist here, CpU with CE = 1
9:      jr      $ra
        nop

        TRIGGER trigger_fetch_misaligned, fetch_misaligned_resume
        la      $t2, fetch_misaligned_resume
        addiu   $t2, $t2, 2         # a jump target that is not word aligned
        jr      $t2
        nop
fetch_misaligned_resume:
9:      jr      $ra
        nop

        TRIGGER trigger_in_delay_slot, delay_slot_branch
delay_slot_branch:
        beq     $zero, $zero, 9f
        syscall                     # in the delay slot: EPC = the branch, Cause.BD = 1
9:      jr      $ra
        nop

# Software interrupt: Cause.IP0 with SR.IM0 and IEc set interrupts; masked, it must not.
        TRIGGER trigger_soft_interrupt, soft_interrupt_site
        li      $t2, 0x100
        mtc0    $t2, $13            # request software interrupt 0
        mfc0    $t3, $12
        nop
        ori     $t3, $t3, 0x101     # IM0 | IEc
soft_interrupt_site:
        mtc0    $t3, $12
        nop
        nop
9:      mfc0    $t3, $12
        nop
        andi    $t3, $t3, 0xFEFE    # IM0 and IEc off again
        mtc0    $t3, $12
        jr      $ra
        nop

        .globl  trigger_masked_interrupt
trigger_masked_interrupt:
        li      $t2, 0x100
        mtc0    $t2, $13            # request software interrupt 0 ...
        mfc0    $t3, $12
        nop
        ori     $t3, $t3, 0x001     # ... but only IEc: IM0 stays clear
        mtc0    $t3, $12
        nop
        nop
        andi    $t3, $t3, 0xFFFE
        mtc0    $t3, $12
        mtc0    $zero, $13
        jr      $ra
        nop

# RFE pops the KU/IE stack: old <- old, previous <- old, current <- previous.
        .globl  rfe_result
rfe_result:
        mfc0    $t3, $12
        li      $t2, 0x30           # KUo=1 IEo=1, previous and current 0
        li      $t4, ~0x3F
        and     $t4, $t3, $t4
        or      $t4, $t4, $t2
        mtc0    $t4, $12
        nop
        rfe
        mfc0    $v0, $12
        nop
        mtc0    $t3, $12
        jr      $ra
        andi    $v0, $v0, 0x3F
