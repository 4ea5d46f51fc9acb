# Start-up code for PlayStation programs: clears the BSS (a real BIOS does not always), calls
# main, and reports main's return value through the exit debug port 0x1F802082.
        .set noreorder
        .section .text.start, "ax"
        .globl _start
_start:
        la      $t0, __bss_start
        la      $t1, __bss_end
1:      beq     $t0, $t1, 2f
        nop
        sw      $zero, 0($t0)
        b       1b
        addiu   $t0, $t0, 4
2:      jal     main
        nop
        lui     $t0, 0x1F80
        sh      $v0, 0x2082($t0)
3:      b       3b
        nop
