# DMA, root counter and MDEC test programs (issue 5).
psx_add_rom_test(dma_modes SOURCES dma_modes.c)
psx_add_rom_test(timers_counts SOURCES timers_counts.c)
psx_add_rom_test(mdec_decode SOURCES mdec_decode.c)
psx_add_rom_test(timers_video SOURCES timers_video.c)
