# SIO0 test programs: pad and memory card protocols through the registers, without a BIOS.
# sio_pad: expect_command checks 2 per byte. Idle status 2 x 1, digital read 5 bytes 10, empty
# slot 2, DualShock: two 5-byte commands 20 + ten 9-byte commands 180 + 2: 2 + 10 + 2 + 202 = 216.
psx_add_rom_test(sio_pad SOURCES sio_pad.c FRAMES 120 CHECKS 216 ARGS --pad2 dualshock)
# sio_memcard (checks that run only on a failure path not counted): card_read 9 (header 6, sector
# 2, end 1), card_write 4. Get ID 10 bytes x 2 = 20; round trip: read + 3, write + 1, read + 3,
# 1, write + 1, read, 1, write + 1 = 12 + 5 + 12 + 1 + 5 + 9 + 1 + 5 = 50; bad sector read 20;
# header frame read + 3 = 12. 20 + 50 + 20 + 12 = 102.
psx_add_rom_test(sio_memcard SOURCES sio_memcard.c FRAMES 300 CHECKS 102
  ARGS --memcard1 ${CMAKE_CURRENT_BINARY_DIR}/sio_memcard.mcd)
