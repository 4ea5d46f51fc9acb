# DMA, root counter and MDEC test programs (issue 5).
# dma_modes: OTC 1 + 15 entries + 7, DICR rules 6, OTC time 4, chopping 4, block mode 5 + 1
# (mdec_idle_check), linked list 3 + 1 = 47.
psx_add_rom_test(dma_modes SOURCES dma_modes.c CHECKS 47)
# timers_counts: 3 check_ratio calls + 2 + 4 + 5 + 2 = 16.
psx_add_rom_test(timers_counts SOURCES timers_counts.c CHECKS 16)
# mdec_decode: reset status 1; two table uploads with a send() check each, 2; mono block: send 1
# + 2 + 64 pixels + 1; 15-bit: send 1 + 1 + 256 pixels. 1 + 2 + 68 + 258 = 329.
psx_add_rom_test(mdec_decode SOURCES mdec_decode.c CHECKS 329)
# timers_video: HBlanks 1 + 5 frames x 2, dot clocks 3, reset at HBlank 3, VBlank sync modes 7
# = 24.
psx_add_rom_test(timers_video SOURCES timers_video.c CHECKS 24)
# dma_list_end (issue 59 item 1): run_list() 5 checks x 5 lists; clean end 2, three unclean
# markers 3 each, toggle 2: 25 + 2 + 9 + 2 = 38.
psx_add_rom_test(dma_list_end SOURCES dma_list_end.c CHECKS 38)
# timers_dots (issue 59 item 3): one check per display mode, 5 widths x NTSC/PAL = 10.
psx_add_rom_test(timers_dots SOURCES timers_dots.c CHECKS 10)
