# SIO0 test programs: pad and memory card protocols through the registers, without a BIOS.
psx_add_rom_test(sio_pad SOURCES sio_pad.c FRAMES 120 ARGS --pad2 dualshock)
psx_add_rom_test(sio_memcard SOURCES sio_memcard.c FRAMES 300
  ARGS --memcard1 ${CMAKE_CURRENT_BINARY_DIR}/sio_memcard.mcd)
