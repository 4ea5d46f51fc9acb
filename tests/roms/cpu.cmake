# CPU, bus, exception and boot test programs.
psx_add_rom_test(hello SOURCES hello.c)
psx_add_rom_test(cpu_pipeline SOURCES cpu_pipeline.c cpu_pipeline.S)
psx_add_rom_test(cpu_exceptions SOURCES cpu_exceptions.c cpu_exceptions.S)
psx_add_rom_test(cpu_memory SOURCES cpu_memory.c cpu_memory.S)
psx_add_rom_test(cpu_alu SOURCES cpu_alu.c)

# The project's boot ROM exercises the BIOS boot + side-load path without Sony's BIOS.
psx_add_rom_image(bootrom SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bootrom.S
                  LINKER_SCRIPT ${CMAKE_CURRENT_SOURCE_DIR}/bootrom.ld)
add_test(NAME rom.bootrom_sideload
  COMMAND ${CMAKE_COMMAND} -DEXPECT_CODE=0 "-DEXPECT_OUTPUT=psxrl boot ROM\nhello from the PlayStation"
          -DCOMMAND=$<TARGET_FILE:psxrl>|run|--bios|${CMAKE_CURRENT_BINARY_DIR}/bootrom.bin|--exe|${CMAKE_CURRENT_BINARY_DIR}/hello.exe|--frames|60|--expect-exit
          -P ${PROJECT_SOURCE_DIR}/tests/expect.cmake)
