# BIOS call stubs for the C-library calls that call back into the program or end it (psx-spx
# "BIOS Function Summary"): bios_stdlib.c and bios_exit.c.
#include "bios_call.inc"

        .set    noreorder
        .text
        BIOS    bios_exit, 0xA0, 0x06
        BIOS    bios_atof, 0xA0, 0x0B
        BIOS    bios_qsort, 0xA0, 0x31
        BIOS    bios_strtod, 0xA0, 0x32
        BIOS    bios_lsearch, 0xA0, 0x35
        BIOS    bios_bsearch, 0xA0, 0x36
        BIOS    bios__exit, 0xA0, 0x3A
        BIOS    bios_exit_b0, 0xB0, 0x38
