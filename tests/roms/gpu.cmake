# GPU test programs: each draws a primitive family through GP0 writes, reads pixels back with
# GP0(C0h) and writes its screen and VRAM as PNGs into the build tree (look at them).
foreach(name gpu_polygons gpu_lines_rects gpu_vram)
  psx_add_rom_test(${name} SOURCES ${name}.c FRAMES 60
    ARGS --screenshot ${CMAKE_CURRENT_BINARY_DIR}/${name}_screen.png --vram ${CMAKE_CURRENT_BINARY_DIR}/${name}_vram.png)
endforeach()
# The same primitive families fed through DMA: OTC-cleared ordering table sent as a DMA2 linked
# list, VRAM uploads and read-back by DMA2 block mode.
psx_add_rom_test(gpu_dma SOURCES gpu_dma.c FRAMES 60
  ARGS --screenshot ${CMAKE_CURRENT_BINARY_DIR}/gpu_dma_screen.png --vram ${CMAKE_CURRENT_BINARY_DIR}/gpu_dma_vram.png)
