# DMA, root counter and MDEC test programs (issue 5).
# dma_modes: OTC 1 + 15 entries + 7, OTC without trigger 1, DICR rules 6, OTC time 4, chopping 4,
# block mode 5 + 1 (mdec_idle_check), linked list 3 + 1 = 48.
psx_add_rom_test(dma_modes SOURCES dma_modes.c CHECKS 48)
# timers_counts: 3 check_ratio calls + 2 + 4 + 5 + 2 = 16.
psx_add_rom_test(timers_counts SOURCES timers_counts.c CHECKS 16)
# mdec_decode: reset status 1; two table uploads with a send() check each, 2; 4-bit heart block:
# send 1 + 1 + 8 words; 8-bit heart block: send 1 + 1 + 2 + idle 1; 15-bit: send 1 + 1 + 256
# pixels. 1 + 2 + 10 + 5 + 258 = 276.
psx_add_rom_test(mdec_decode SOURCES mdec_decode.c CHECKS 276)
# timers_video: HBlanks 1 + 5 frames x 2, dot clocks 3, reset at HBlank 3, VBlank sync modes 7
# = 24.
psx_add_rom_test(timers_video SOURCES timers_video.c CHECKS 24)
# dma_list_end (issue 59 item 1): run_list() 5 checks x 5 lists; clean end 2, three unclean
# markers 3 each, toggle 2: 25 + 2 + 9 + 2 = 38.
psx_add_rom_test(dma_list_end SOURCES dma_list_end.c CHECKS 38)
# timers_dots (issue 59 item 3): one check per display mode, 5 widths x NTSC/PAL = 10.
psx_add_rom_test(timers_dots SOURCES timers_dots.c CHECKS 10)
# timers_reset (issue 59 item 3): 3 reads after a reset, each after a check that the count had
# passed 10 = 6. Run by both CPUs: the recompiler makes I/O stores natively.
psx_add_rom_test(timers_reset SOURCES timers_reset.c timers_reset.S CHECKS 6)
psx_add_run_test(rom.timers_reset_recompiler CODE 0 CHECKS 6
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/timers_reset.exe --frames 600 --expect-exit --cpu recompiler)
# dma_timing (issue 59 item 8): GPU sync mode 1, 65 block sizes; one burst; 64 chopping pairs less
# the 3 the console's program could not time and 2 not matched; linked lists 3 (complete) + 2 x 3
# (endless); SPU sync mode 1, 4: 65 + 1 + 59 + 9 + 4 = 138.
psx_add_rom_test(dma_timing SOURCES dma_timing.c CHECKS 138)
# The same timings with the recompiler: its deadline checks decide when the DMA's turns come.
psx_add_run_test(rom.dma_timing_recompiler CODE 0 CHECKS 138
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/dma_timing.exe --frames 600 --expect-exit --cpu recompiler)
