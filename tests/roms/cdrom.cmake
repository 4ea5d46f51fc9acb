# CD-ROM test programs and the test discs they run with, built by mkdisc at build time.

# DATA.BIN holds 4096 letters (two sectors), byte i = 'A' + (i * 7 + 3) % 26.
set(CDROM_DATA ${CMAKE_CURRENT_BINARY_DIR}/cdrom_data.bin)
set(letters ABCDEFGHIJKLMNOPQRSTUVWXYZ)
set(cdrom_data_text "")
foreach(i RANGE 0 4095)
  math(EXPR k "(${i} * 7 + 3) % 26")
  string(SUBSTRING ${letters} ${k} 1 c)
  string(APPEND cdrom_data_text ${c})
endforeach()
file(CONFIGURE OUTPUT ${CDROM_DATA} CONTENT "${cdrom_data_text}")
add_custom_command(OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/cdrom_test.cue ${CMAKE_CURRENT_BINARY_DIR}/cdrom_test.bin
  COMMAND mkdisc -o ${CMAKE_CURRENT_BINARY_DIR}/cdrom_test.cue ${CDROM_DATA}=DATA.BIN
  DEPENDS mkdisc ${CDROM_DATA} VERBATIM)
add_custom_target(cdrom_test_disc ALL DEPENDS ${CMAKE_CURRENT_BINARY_DIR}/cdrom_test.cue)
# 44 checks run once, one in the two-sector loop twice: 46.
psx_add_rom_test(cdrom_controller SOURCES cdrom_controller.c CHECKS 46
                 ARGS --disc ${CMAKE_CURRENT_BINARY_DIR}/cdrom_test.cue)

# A bootable disc: the HLE fast boot reads SYSTEM.CNF and loads BOOT.EXE from it.
psx_add_exe(cdrom_boot SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/cdrom_boot.c)
add_custom_command(OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/cdrom_boot.cue ${CMAKE_CURRENT_BINARY_DIR}/cdrom_boot.bin
  COMMAND mkdisc -o ${CMAKE_CURRENT_BINARY_DIR}/cdrom_boot.cue --exe ${CMAKE_CURRENT_BINARY_DIR}/cdrom_boot.exe
          --exe-name BOOT.EXE --cnf ${CMAKE_CURRENT_SOURCE_DIR}/cdrom_boot.cnf --region E
  DEPENDS mkdisc cdrom_boot ${CMAKE_CURRENT_BINARY_DIR}/cdrom_boot.exe ${CMAKE_CURRENT_SOURCE_DIR}/cdrom_boot.cnf VERBATIM)
add_custom_target(cdrom_boot_disc ALL DEPENDS ${CMAKE_CURRENT_BINARY_DIR}/cdrom_boot.cue)
psx_add_run_test(rom.cdrom_boot_hle CODE 0 CHECKS 1
  RUN --disc ${CMAKE_CURRENT_BINARY_DIR}/cdrom_boot.cue --frames 60 --expect-exit)
