# Entry of bios_exec's child program: records a0, a1, sp and gp as Exec/LoadExec set them in the
# scratchpad (the C code's prologue would move sp), then runs child_main with a0/a1 unchanged;
# child_main's return goes straight back to Exec's return address.
        .set noreorder
        .section .text.start, "ax"
        .globl  _start
_start:
        lui     $t0, 0x1F80
        sw      $a0, 0x20($t0)
        sw      $a1, 0x24($t0)
        sw      $sp, 0x28($t0)
        j       child_main
        sw      $gp, 0x2C($t0)
