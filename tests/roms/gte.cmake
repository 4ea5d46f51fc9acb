# GTE test programs: the GTE driven through the CPU's COP2 instructions.
psx_add_rom_test(gte_basic SOURCES gte_basic.c FRAMES 60 CHECKS 32)  # one per CHECK_EQ, each run once
