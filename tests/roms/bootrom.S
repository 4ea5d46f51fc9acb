# The project's minimal boot ROM (a 512 KiB image, no Sony code): sets up memory control, the
# interrupt controller and COP0 as a BIOS would, announces itself on the dev-kit DUART, and jumps
# to the shell entry 0x80030000, where the emulator side-loads the EXE exactly as it does after
# a real BIOS.
        .set noreorder
        .text
        .globl  _start
_start:
        lui     $t0, 0x1F80
        li      $t1, 0x1F000000
        sw      $t1, 0x1000($t0)    # expansion 1 base
        li      $t1, 0x1F802000
        sw      $t1, 0x1004($t0)    # expansion 2 base
        li      $t1, 0x0013243F
        sw      $t1, 0x1008($t0)    # expansion 1 delay/size
        li      $t1, 0x00003022
        sw      $t1, 0x100C($t0)    # expansion 3 delay/size
        li      $t1, 0x0013243F
        sw      $t1, 0x1010($t0)    # BIOS ROM delay/size
        li      $t1, 0x200931E1
        sw      $t1, 0x1014($t0)    # SPU delay
        li      $t1, 0x00020843
        sw      $t1, 0x1018($t0)    # CD-ROM delay
        li      $t1, 0x00070777
        sw      $t1, 0x101C($t0)    # expansion 2 delay/size
        li      $t1, 0x00031125
        sw      $t1, 0x1020($t0)    # common delay
        li      $t1, 0x00000B88
        sw      $t1, 0x1060($t0)    # RAM_SIZE: 2 MiB, mirrored over 8 MiB
        sw      $zero, 0x1074($t0)  # I_MASK: nothing enabled
        sw      $zero, 0x1070($t0)  # I_STAT: acknowledge everything
        lui     $t2, 0xFFFE
        li      $t1, 0x0001E988
        sw      $t1, 0x0130($t2)    # cache control as the BIOS sets it
        mtc0    $zero, $12          # SR: kernel mode, interrupts off, RAM exception vectors

        # A0h/B0h/C0h: this ROM has no kernel; each vector just returns ("jr $ra; nop"), so
        # programs' BIOS calls return and the emulator's putchar hooks still print.
        li      $t6, 0x03E00008
        sw      $t6, 0x00A0($zero)
        sw      $zero, 0x00A4($zero)
        sw      $t6, 0x00B0($zero)
        sw      $zero, 0x00B4($zero)
        sw      $t6, 0x00C0($zero)
        sw      $zero, 0x00C4($zero)

        la      $t3, banner
1:      lbu     $t4, 0($t3)
        addiu   $t3, $t3, 1
        beqz    $t4, 2f
        nop
        b       1b
        sb      $t4, 0x2023($t0)    # DUART channel A transmit
2:      li      $sp, 0x801FFFF0
        move    $fp, $sp
        li      $t5, 0x80030000
        jr      $t5
        nop

banner:
        .asciz  "psxrl boot ROM\n"
