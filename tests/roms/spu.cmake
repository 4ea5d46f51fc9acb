# SPU test programs.
psx_add_rom_test(spu_voices SOURCES spu_voices.c)
psx_add_rom_test(spu_dma SOURCES spu_dma.c)
