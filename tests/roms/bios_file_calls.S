# BIOS call stubs for the file, CD-ROM and memory card test programs (bios_files, bios_memcard),
# numbers from psx-spx "BIOS Function Summary".
        .set noreorder
        .text
#include "bios_call.inc"

        BIOS    file_open, 0xA0, 0x00
        BIOS    file_lseek, 0xA0, 0x01
        BIOS    file_read, 0xA0, 0x02
        BIOS    file_write, 0xA0, 0x03
        BIOS    file_close, 0xA0, 0x04
        BIOS    file_getc, 0xA0, 0x08
        BIOS    file_putc, 0xA0, 0x09
        BIOS    tty_getchar, 0xA0, 0x3B
        BIOS    bu_init, 0xA0, 0x70
        BIOS    cd_init, 0xA0, 0x71
        BIOS    cd_remove, 0xA0, 0x72
        BIOS    cd_get_lbn, 0xA0, 0xA4
        BIOS    cd_read_sector, 0xA0, 0xA5
        BIOS    cd_get_status, 0xA0, 0xA6
        BIOS    card_info, 0xA0, 0xAB
        BIOS    card_load, 0xA0, 0xAC
        BIOS    card_auto, 0xA0, 0xAD
        BIOS    card_write_test, 0xA0, 0xAF
        BIOS    b_open, 0xB0, 0x32
        BIOS    b_read, 0xB0, 0x34
        BIOS    b_close, 0xB0, 0x36
        BIOS    file_cd, 0xB0, 0x40
        BIOS    first_file, 0xB0, 0x42
        BIOS    next_file, 0xB0, 0x43
        BIOS    file_erase, 0xB0, 0x45
        BIOS    init_card, 0xB0, 0x4A
        BIOS    start_card, 0xB0, 0x4B
        BIOS    stop_card, 0xB0, 0x4C
        BIOS    card_write, 0xB0, 0x4E
        BIOS    card_read, 0xB0, 0x4F
        BIOS    new_card, 0xB0, 0x50
        BIOS    get_errno, 0xB0, 0x54
        BIOS    get_error, 0xB0, 0x55
        BIOS    card_status, 0xB0, 0x5C
        BIOS    card_wait, 0xB0, 0x5D
        BIOS    tty_gets, 0xA0, 0x3D
        BIOS    bufs_cb_0, 0xA0, 0xA7
        BIOS    bufs_cb_4, 0xA0, 0xAE
        BIOS    b_gets, 0xB0, 0x3E
        BIOS    file_format, 0xB0, 0x41
        BIOS    file_rename, 0xB0, 0x44
        BIOS    file_undelete, 0xB0, 0x46
        BIOS    print_devices, 0xB0, 0x49
        BIOS    card_chan, 0xB0, 0x58
        BIOS    set_card_find_mode, 0xC0, 0x1A
        BIOS    get_card_find_mode, 0xC0, 0x1D
