# CPU, bus, exception and boot test programs.
psx_add_rom_test(hello SOURCES hello.c)
psx_add_rom_test(cpu_pipeline SOURCES cpu_pipeline.c cpu_pipeline.S)
psx_add_rom_test(cpu_exceptions SOURCES cpu_exceptions.c cpu_exceptions.S)
psx_add_rom_test(cpu_memory SOURCES cpu_memory.c cpu_memory.S)
psx_add_rom_test(cpu_alu SOURCES cpu_alu.c)

# The project's boot ROM exercises the BIOS boot + side-load path without Sony's BIOS.
psx_add_rom_image(bootrom SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bootrom.S
                  LINKER_SCRIPT ${CMAKE_CURRENT_SOURCE_DIR}/bootrom.ld
                  DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/rom_init.inc)
add_test(NAME rom.bootrom_sideload
  COMMAND ${CMAKE_COMMAND} -DEXPECT_CODE=0 "-DEXPECT_OUTPUT=psxrl boot ROM\nhello from the PlayStation"
          -DCOMMAND=$<TARGET_FILE:psxrl>|run|--bios|${CMAKE_CURRENT_BINARY_DIR}/bootrom.bin|--exe|${CMAKE_CURRENT_BINARY_DIR}/hello.exe|--frames|60|--expect-exit
          -P ${PROJECT_SOURCE_DIR}/tests/expect.cmake)

# HLE BIOS calls: the text is what C's printf gives for the same formats and arguments.
psx_add_exe(bios_hle SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bios_hle.c ${CMAKE_CURRENT_SOURCE_DIR}/bios_calls.S)
add_test(NAME rom.bios_hle
  COMMAND ${CMAKE_COMMAND} -DEXPECT_CODE=0
          "-DEXPECT_OUTPUT=AB\nputs line\nstd_out_puts line\n[-42|7|3000000000|beef|BEEF|10]\n[   42|42   |00042|+42| 42]\n[0xff|010|007|     abc|z   |%]\n[   -12|six|ok]\n1 2 3 4 5 6\nbios_hle: 10 checks, 0 failures"
          -DCOMMAND=$<TARGET_FILE:psxrl>|run|--exe|${CMAKE_CURRENT_BINARY_DIR}/bios_hle.exe|--frames|60|--expect-exit
          -P ${PROJECT_SOURCE_DIR}/tests/expect.cmake)
psx_add_exe(bios_putchar SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bios_putchar.c ${CMAKE_CURRENT_SOURCE_DIR}/bios_calls.S)
add_test(NAME rom.bios_putchar_with_rom
  COMMAND ${CMAKE_COMMAND} -DEXPECT_CODE=0 "-DEXPECT_OUTPUT=psxrl boot ROM\nok\n"
          -DCOMMAND=$<TARGET_FILE:psxrl>|run|--bios|${CMAKE_CURRENT_BINARY_DIR}/bootrom.bin|--exe|${CMAKE_CURRENT_BINARY_DIR}/bios_putchar.exe|--frames|60|--expect-exit
          -P ${PROJECT_SOURCE_DIR}/tests/expect.cmake)
psx_add_rom_test(watch_writes SOURCES watch_writes.c)
psx_add_rom_test(cpu_breakpoints SOURCES cpu_breakpoints.c cpu_breakpoints.S)
psx_add_rom_test(cpu_dcache SOURCES cpu_dcache.c cpu_dcache.S)
psx_add_rom_test(cpu_icache SOURCES cpu_icache.c cpu_icache.S)
psx_add_exe(cpu_dcache_hang SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/cpu_dcache_hang.c)
add_test(NAME rom.cpu_dcache_hang
  COMMAND ${CMAKE_COMMAND} -DEXPECT_CODE=3 "-DEXPECT_OUTPUT=scratchpad access at 0x1F800000 in data-cache mode hangs the bus"
          -DCOMMAND=$<TARGET_FILE:psxrl>|run|--exe|${CMAKE_CURRENT_BINARY_DIR}/cpu_dcache_hang.exe|--frames|60|--expect-exit
          -P ${PROJECT_SOURCE_DIR}/tests/expect.cmake)
