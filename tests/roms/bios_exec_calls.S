# BIOS call stubs for the executable and miscellaneous kernel call tests (bios_exec, bios_misc),
# numbers from psx-spx "BIOS Function Summary".
        .set noreorder
        .text
#include "bios_call.inc"

        BIOS    load_test, 0xA0, 0x41
        BIOS    load_exe, 0xA0, 0x42
        BIOS    exec_exe, 0xA0, 0x43
        BIOS    load_exec, 0xA0, 0x51
        BIOS    a0_return_zero_57, 0xA0, 0x57
        BIOS    cd_async_seekl, 0xA0, 0x78
        BIOS    cd_async_get_status, 0xA0, 0x7C
        BIOS    cd_async_read_sector, 0xA0, 0x7E
        BIOS    cd_async_set_mode, 0xA0, 0x81
        BIOS    set_mem, 0xA0, 0x9F
        BIOS    warm_boot, 0xA0, 0xA0
        BIOS    install_exception_handlers, 0xC0, 0x07
        BIOS    sys_init_memory, 0xC0, 0x08
        BIOS    c0_return_zero_0e, 0xC0, 0x0E
