# CPU, bus, exception and boot test programs.
# CHECKS: one per CHECK_EQ call site unless a comment gives the arithmetic.
psx_add_rom_test(hello SOURCES hello.c CHECKS 2 OUTPUT "hello from the PlayStation\n")
psx_add_rom_test(cpu_pipeline SOURCES cpu_pipeline.c cpu_pipeline.S CHECKS 11)
# 10 expect() calls x 5 checks + 5 direct checks between them + 6 for the software interrupt,
# masked interrupt and RFE = 61.
psx_add_rom_test(cpu_exceptions SOURCES cpu_exceptions.c cpu_exceptions.S CHECKS 61)
psx_add_rom_test(cpu_memory SOURCES cpu_memory.c cpu_memory.S CHECKS 21)
psx_add_rom_test(cpu_alu SOURCES cpu_alu.c CHECKS 27)

# The project's boot ROM exercises the BIOS boot + side-load path without Sony's BIOS.
psx_add_rom_image(bootrom SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bootrom.S
                  LINKER_SCRIPT ${CMAKE_CURRENT_SOURCE_DIR}/bootrom.ld
                  DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/rom_init.inc)
psx_add_run_test(rom.bootrom_sideload CODE 0 CHECKS 2 OUTPUT "psxrl boot ROM\nhello from the PlayStation"
  RUN --bios ${CMAKE_CURRENT_BINARY_DIR}/bootrom.bin --exe ${CMAKE_CURRENT_BINARY_DIR}/hello.exe --frames 60 --expect-exit)

# HLE BIOS calls: the text is what C's printf gives for the same formats and arguments.
psx_add_exe(bios_hle SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bios_hle.c ${CMAKE_CURRENT_SOURCE_DIR}/bios_calls.S)
psx_add_run_test(rom.bios_hle CODE 0 CHECKS 12
  OUTPUT "AB\nputs line\nstd_out_puts line\n[-42|7|3000000000|beef|BEEF|10]\n[   42|42   |00042|+42| 42]\n[0xff|010|007|     abc|z   |%]\n[   -12|six|ok]\n1 2 3 4 5 6\nbios_hle: 12 checks, 0 failures"
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/bios_hle.exe --frames 60 --expect-exit)
psx_add_exe(bios_putchar SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bios_putchar.c ${CMAKE_CURRENT_SOURCE_DIR}/bios_calls.S)
# No checks of its own: the text is the test.
psx_add_run_test(rom.bios_putchar_with_rom CODE 0 OUTPUT "psxrl boot ROM\nok\n"
  RUN --bios ${CMAKE_CURRENT_BINARY_DIR}/bootrom.bin --exe ${CMAKE_CURRENT_BINARY_DIR}/bios_putchar.exe --frames 60 --expect-exit)
psx_add_rom_test(watch_writes SOURCES watch_writes.c CHECKS 5)
# COP0 breakpoints (issue 59 item 2): 14 expected breaks of 6 checks, 12 expected non-breaks of 2,
# 15 checks between them: 84 + 24 + 15 = 123. Run by both CPUs: the recompiler leaves armed
# breakpoints to the interpreter's code, which this holds it to.
psx_add_rom_test(cpu_breakpoints SOURCES cpu_breakpoints.c cpu_breakpoints.S CHECKS 123)
psx_add_run_test(rom.cpu_breakpoints_recompiler CODE 0 CHECKS 123
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/cpu_breakpoints.exe --frames 600 --expect-exit --cpu recompiler)
# Coprocessor exceptions (issue 59 item 7): ps1-tests cpu/cop's 17 cases, 10 with no exception (1
# check) and 7 with one (3), the PRId read, and 4 psx-spx cases (3 + 2 + 2 + 1):
# 10 + 21 + 1 + 8 = 40.
psx_add_rom_test(cpu_cop SOURCES cpu_cop.c cpu_cop.S CHECKS 40)
psx_add_run_test(rom.cpu_cop_recompiler CODE 0 CHECKS 40
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/cpu_cop.exe --frames 600 --expect-exit --cpu recompiler)
# Code run from I/O ports (issue 59 item 7, ps1-tests cpu/code-in-io): 4 cases that run (1
# check), 3 that raise a bus error (2), and the scratchpad's EPC: 4 + 6 + 1 = 11.
psx_add_rom_test(cpu_code_in_io SOURCES cpu_code_in_io.c cpu_code_in_io.S CHECKS 11)
psx_add_run_test(rom.cpu_code_in_io_recompiler CODE 0 CHECKS 11
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/cpu_code_in_io.exe --frames 600 --expect-exit --cpu recompiler)
# The cache programs check each case once (10 and 12 sites).
psx_add_rom_test(cpu_dcache SOURCES cpu_dcache.c cpu_dcache.S CHECKS 10)
psx_add_rom_test(cpu_icache SOURCES cpu_icache.c cpu_icache.S CHECKS 12)
# Load timing: one check per measured sequence (SEQUENCES in the source).
psx_add_rom_test(cpu_load_timing SOURCES cpu_load_timing.c cpu_load_timing.S CHECKS 9)
# On-chip port load timing (issue 59 item 5, pcsx-redux load-timings): 8 spacings, 7 reader positions.
psx_add_rom_test(cpu_load_sweep SOURCES cpu_load_sweep.c cpu_load_sweep.S CHECKS 15)
psx_add_run_test(rom.cpu_load_sweep_recompiler CODE 0 CHECKS 15
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/cpu_load_sweep.exe --frames 600 --expect-exit --cpu recompiler)
psx_add_rom_test(cpu_icache_code SOURCES cpu_icache_code.c cpu_icache.S bios_calls.S CHECKS 9)
psx_add_exe(cpu_dcache_hang SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/cpu_dcache_hang.c)
psx_add_run_test(rom.cpu_dcache_hang CODE 3 OUTPUT "scratchpad access at 0x1F800000 in data-cache mode hangs the bus"
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/cpu_dcache_hang.exe --frames 60 --expect-exit)
# Narrow stores to I/O registers (issue 59 item 6): 3 word registers x 3 for RAM, scratchpad and
# expansion 2, + 2 narrow reads of expansion 2, + 3 DMA registers x 3, + 4 halfword registers x 2
# = 9 + 2 + 9 + 8 = 28. Run by both CPUs: the recompiler's I/O stores take their own path.
psx_add_rom_test(cpu_io_width SOURCES cpu_io_width.c CHECKS 28)
psx_add_run_test(rom.cpu_io_width_recompiler CODE 0 CHECKS 28
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/cpu_io_width.exe --frames 600 --expect-exit --cpu recompiler)
# Load cost by region and width (issue 59 item 5): 12 regions x 3 widths = 36.
psx_add_rom_test(cpu_access_time SOURCES cpu_access_time.c cpu_access_time.S CHECKS 48)
psx_add_run_test(rom.cpu_access_time_recompiler CODE 0 CHECKS 48
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/cpu_access_time.exe --frames 600 --expect-exit --cpu recompiler)
