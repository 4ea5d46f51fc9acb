# The HLE kernel's file functions: cdrom: files on cdrom.cmake's disc (DATA.BIN) and tty: handles,
# and the memory card functions on a card in slot 1 (a card file in the build tree, created on the
# first write; the program erases its own file from an earlier run first). CHECKS: one per
# CHECK_EQ call site, each run once.
psx_add_rom_test(bios_files SOURCES bios_files.c bios_file_calls.S bios_calls.S CHECKS 48
                 ARGS --disc ${CMAKE_CURRENT_BINARY_DIR}/cdrom_test.cue)
psx_add_rom_test(bios_memcard SOURCES bios_memcard.c bios_file_calls.S bios_calls.S CHECKS 61
                 ARGS --memcard1 ${CMAKE_CURRENT_BINARY_DIR}/bios_memcard.mcd)
# format, rename, undelete, the card find mode, _card_chan and bufs_cb_* on a card in slot 1 (its
# own card file; the program formats it first).
psx_add_rom_test(bios_card_dir SOURCES bios_card_dir.c bios_file_calls.S bios_calls.S CHECKS 41
                 ARGS --memcard1 ${CMAKE_CURRENT_BINARY_DIR}/bios_card_dir.mcd)
# The asynchronous CD calls on cdrom.cmake's disc, gets, SetMem, InstallExceptionHandlers,
# SysInitMemory, PrintInstalledDevices (its list names the CD-ROM device) and "returns 0" entries.
psx_add_rom_test(bios_misc SOURCES bios_misc.c bios_exec_calls.S bios_file_calls.S bios_calls.S CHECKS 28
                 OUTPUT "CD-ROM" ARGS --disc ${CMAKE_CURRENT_BINARY_DIR}/cdrom_test.cue)
