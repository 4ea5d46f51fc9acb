# SPU test programs.
# spu_voices: two manual uploads with 1 check each + 11 in main = 13.
psx_add_rom_test(spu_voices SOURCES spu_voices.c CHECKS 13)
# spu_dma: spu_transfer runs 7 checks. Upload and read back: 4 transfers + 2 + 16 + 16 = 62;
# transfer IRQ: 2 transfers + 4 = 18; voices 10. 62 + 18 + 10 = 90.
psx_add_rom_test(spu_dma SOURCES spu_dma.c CHECKS 90)
