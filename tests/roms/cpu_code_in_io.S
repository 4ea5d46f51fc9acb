# Code run from I/O ports (issue 59 item 7): a general-vector handler that counts exceptions,
# records Cause and EPC and returns to $ra, the caller of the routine under test (an instruction
# bus error leaves no instruction to resume at), the routine the tests copy: JR $RA; NOP, and the
# call that runs it with a0 = 0: the words the MDEC's ports hold run as LB $a0, 8($a0) (status
# 80840008h after that store), which then reads RAM rather than whatever a0 held.
        .set noreorder
        .set noat
        .text

# io_record: +0 Cause, +4 EPC, +8 count
        .globl io_record
        .data
io_record:
        .word   0, 0, 0
        .text

# Copied to 0x80000080, the general exception vector.
        .globl io_vector_stub
io_vector_stub:
        j       io_handler
        nop

io_handler:
        la      $k0, io_record
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
        jr      $ra
        rfe

# The two words each test stores at its address and calls.
        .globl io_return_code
io_return_code:
        jr      $ra
        nop

# void call_io(uint32_t address): jumps to address with a0 = 0 and the caller's return address.
        .globl call_io
call_io:
        move    $t0, $a0
        jr      $t0
        move    $a0, $zero
