# For psxrl compat's tests (tests/unit/cli_compat_test.cpp): calls BIOS function C0h:7Fh, past
# the end of table C0h (psx-spx "BIOS Function Summary" lists C0h:00h to 1Dh), which no kernel
# implements, so the HLE kernel stops the program there and compat must report that call.
        .set noreorder
        .text
        .globl  main
main:
        li      $t2, 0xC0
        jalr    $t2
        li      $t1, 0x7F
1:      b       1b
        nop
