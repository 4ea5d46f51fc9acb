# The BIOS's GPU call the gpu_timing program makes (psx-spx "BIOS Function Summary").
        .set noreorder
        .text
#include "bios_call.inc"

        BIOS    gpu_sync, 0xA0, 0x4E
