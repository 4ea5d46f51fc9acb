# GPU test programs: each draws a primitive family through GP0 writes, reads pixels back with
# GP0(C0h) and writes its screen and VRAM as PNGs into the build tree (look at them).
# CHECKS per program:
# gpu_polygons: fill rule 10 rows x 10 pixels, quad 8 + 2, Gouraud 31, dither 8 x 8, texels
# 4 rows x 16 + 2, blend 2, big scene 2: 100 + 10 + 31 + 64 + 66 + 2 + 2 = 275.
# gpu_lines_rects: line 13, diagonal 11, Gouraud line 31, polyline 5, rectangles 9, textured 8 +
# flipped 8, blend modes 4: 60 + 9 + 16 + 4 = 89.
# gpu_vram: fill 5, transfers 10, mask 3, status and info 10, VBlank 1 = 29.
set(gpu_polygons_checks 275)
set(gpu_lines_rects_checks 89)
set(gpu_vram_checks 29)
set(gpu_dma_checks 737)
foreach(name gpu_polygons gpu_lines_rects gpu_vram)
  psx_add_rom_test(${name} SOURCES ${name}.c FRAMES 60 CHECKS ${${name}_checks}
    ARGS --screenshot ${CMAKE_CURRENT_BINARY_DIR}/${name}_screen.png --vram ${CMAKE_CURRENT_BINARY_DIR}/${name}_vram.png)
endforeach()
# The same primitive families fed through DMA: OTC-cleared ordering table sent as a DMA2 linked
# list, VRAM uploads and read-back by DMA2 block mode.
# gpu_dma CHECKS: gd_upload runs 3 checks (gd_block), gd_download / gd_read_row / gd_peek 4.
# Set-up: 5 uploads 15 + 2, OT clear 1, OT send 2, + 2 = 22. Polygons: fill rule 10 x (4 + 10),
# quad 4 + 10, bottom 4 + 1, Gouraud 4 + 31, texels 4 x (4 + 16), 6 peeks x (4 + 1) = 304.
# Lines: 4 + 13, 4 + 31, 5 x 5, 4 + 31, 30 x 5 = 262. Rectangles: 9 x 5 + 4 + 8 + 2 x 5 = 67.
# Fill: 9 x 5 = 45. Transfers: 3 + 4 + 15 x 2 = 37. 22 + 304 + 262 + 67 + 45 + 37 = 737.
psx_add_rom_test(gpu_dma SOURCES gpu_dma.c FRAMES 60 CHECKS ${gpu_dma_checks}
  ARGS --screenshot ${CMAKE_CURRENT_BINARY_DIR}/gpu_dma_screen.png --vram ${CMAKE_CURRENT_BINARY_DIR}/gpu_dma_vram.png)
# The same programs through the OpenGL renderer (OSMesa, headless): their checks read VRAM back
# with GP0(C0h), which at any scale is the native view, so they must pass at scale 1 and 4.
foreach(name gpu_polygons gpu_lines_rects gpu_vram gpu_dma)
  foreach(scale 1 4)
    psx_add_run_test(rom.${name}_gl${scale} CODE 0 CHECKS ${${name}_checks}
      RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/${name}.exe --frames 60 --expect-exit --renderer gl --scale ${scale})
  endforeach()
endforeach()
# gpu_timing (issue 59 item 8): ps1-tests gpu/gpustat's 12 cases (before, during and after
# rectangles sent by the CPU, a DMA linked list, sync mode 1 in directions 1 and 2) and
# gpu/bandwidth's 14 rows, against the console logs; the BIOS's gpu_sync by psx-spx, DMA off 3 and
# a DMA list 4: 12 + 14 + 7 = 33.
psx_add_rom_test(gpu_timing SOURCES gpu_timing.c gpu_bios_calls.S CHECKS 33)
