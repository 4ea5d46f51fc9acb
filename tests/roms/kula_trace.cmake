# The Kula World RAM trace program (kula_trace.c) on a disc, booted by the cdboot ROM standing in
# for the user's BIOS: tests/unit/rl_kula_test.cpp runs games/kula against it.
psx_add_exe(kula_trace SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/kula_trace.c)
add_custom_command(OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/kula_trace.cue ${CMAKE_CURRENT_BINARY_DIR}/kula_trace.bin
  COMMAND mkdisc -o ${CMAKE_CURRENT_BINARY_DIR}/kula_trace.cue --exe ${CMAKE_CURRENT_BINARY_DIR}/kula_trace.exe
          --exe-name BOOT.EXE --cnf ${CMAKE_CURRENT_SOURCE_DIR}/cdrom_boot.cnf
  DEPENDS mkdisc kula_trace ${CMAKE_CURRENT_BINARY_DIR}/kula_trace.exe ${CMAKE_CURRENT_SOURCE_DIR}/cdrom_boot.cnf VERBATIM)
add_custom_target(kula_trace_disc ALL DEPENDS ${CMAKE_CURRENT_BINARY_DIR}/kula_trace.cue)
