# qsort/lsearch/bsearch, atof/strtod (bios_stdlib.c) and exit/_exit (bios_exit.c) under the HLE
# kernel. CHECKS 26: 18 call sites run once, and faults_on_cop1's 4 run twice (atof, strtod).
psx_add_rom_test(bios_stdlib SOURCES bios_stdlib.c bios_calls.S bios_stdlib_calls.S CHECKS 26)
# The recompiler too: it must take the COP1 instruction's exception in the kernel's stub and hand
# the kernel the comparisons' returns.
psx_add_run_test(rom.bios_stdlib_recompiler CODE 0 CHECKS 26
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/bios_stdlib.exe --frames 600 --expect-exit --cpu recompiler)
# Each exit call ends the run with code 7 and the kernel's message naming it.
foreach(call exit exit_b0 _exit)
  set(fn ${call})
  if(call STREQUAL "exit_b0")
    set(fn exit)
  endif()
  psx_add_exe(bios_exit_${call} SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bios_exit.c
    ${CMAKE_CURRENT_SOURCE_DIR}/bios_stdlib_calls.S DEFINES EXIT_CALL=bios_${call})
  psx_add_run_test(rom.bios_exit_${call} CODE 7 OUTPUT "the program called ${fn}(7)"
    RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/bios_exit_${call}.exe --frames 60)
endforeach()
