# BIOS call stubs as the SDK writes them: load the table address, jump, and set the function
# number in the jump's delay slot; the BIOS returns straight to the C caller.
        .set noreorder
        .text
        .macro  BIOS name, table, fn
        .globl  \name
\name:
        li      $t2, \table
        jr      $t2
        li      $t1, \fn
        .endm

        BIOS    bios_strlen, 0xA0, 0x1B
        BIOS    bios_memcpy, 0xA0, 0x2A
        BIOS    bios_memset, 0xA0, 0x2B
        BIOS    bios_putchar, 0xA0, 0x3C
        BIOS    bios_puts, 0xA0, 0x3E
        BIOS    bios_printf, 0xA0, 0x3F
        BIOS    std_out_putchar, 0xB0, 0x3D
        BIOS    std_out_puts, 0xB0, 0x3F

        .globl  enter_critical_section
enter_critical_section:
        li      $a0, 1
        syscall
        jr      $ra
        nop

        .globl  exit_critical_section
exit_critical_section:
        li      $a0, 2
        syscall
        jr      $ra
        nop
