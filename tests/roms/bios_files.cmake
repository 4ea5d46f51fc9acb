# The HLE kernel's file functions: cdrom: files on cdrom.cmake's disc (DATA.BIN) and tty: handles,
# and the memory card functions on a card in slot 1 (a card file in the build tree, created on the
# first write; the program erases its own file from an earlier run first). CHECKS: one per
# CHECK_EQ call site, each run once.
psx_add_rom_test(bios_files SOURCES bios_files.c bios_file_calls.S bios_calls.S CHECKS 48
                 ARGS --disc ${CMAKE_CURRENT_BINARY_DIR}/cdrom_test.cue)
psx_add_rom_test(bios_memcard SOURCES bios_memcard.c bios_file_calls.S bios_calls.S CHECKS 62
                 ARGS --memcard1 ${CMAKE_CURRENT_BINARY_DIR}/bios_memcard.mcd)
# SetRCnt/StartRCnt/StopRCnt with the F200000xh class values SDKs pass (8 checks, each run once).
psx_add_rom_test(bios_rcnt_class SOURCES bios_rcnt_class.c bios_calls.S CHECKS 8)
# Interrupts taken in a load delay slot keep the loaded value (3 checks).
psx_add_rom_test(bios_irq_load SOURCES bios_irq_load.c bios_calls.S CHECKS 3)
