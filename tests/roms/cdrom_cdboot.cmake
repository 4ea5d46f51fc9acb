# The cdboot boot ROM (tests/roms/cdboot/): boots discs made by mkdisc by reading them through the
# CD-ROM controller itself, as a BIOS does, after following the GPU's interlace fields through
# GPUSTAT bits 31/13 as a BIOS shell does. Needs cdrom.cmake's DATA.BIN (CDROM_DATA) and discs.
set(CDBOOT_DIR ${CMAKE_CURRENT_SOURCE_DIR}/cdboot)
psx_add_rom_image(cdboot_rom
  SOURCES ${CDBOOT_DIR}/rom_start.S ${CDBOOT_DIR}/rom_main.c ${CDBOOT_DIR}/cd.c ${PSX_GUEST_DIR}/runtime.c
  LINKER_SCRIPT ${CDBOOT_DIR}/rom.ld
  DEPENDS ${CDBOOT_DIR}/cd.h ${CMAKE_CURRENT_SOURCE_DIR}/rom_init.inc)
set(CDBOOT_ROM ${CMAKE_CURRENT_BINARY_DIR}/cdboot_rom.bin)

# A disc with a test program that checks what the ROM left it and reads its own data file.
psx_add_exe(cdboot_disc_check SOURCES ${CDBOOT_DIR}/disc_check.c ${CDBOOT_DIR}/cd.c INCLUDES ${CDBOOT_DIR})
add_custom_command(OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/cdboot_test.cue ${CMAKE_CURRENT_BINARY_DIR}/cdboot_test.bin
  COMMAND mkdisc -o ${CMAKE_CURRENT_BINARY_DIR}/cdboot_test.cue --exe ${CMAKE_CURRENT_BINARY_DIR}/cdboot_disc_check.exe
          --exe-name BOOT.EXE --cnf ${CMAKE_CURRENT_SOURCE_DIR}/cdrom_boot.cnf ${CDROM_DATA}=DATA.BIN
  DEPENDS mkdisc cdboot_disc_check ${CMAKE_CURRENT_BINARY_DIR}/cdboot_disc_check.exe
          ${CMAKE_CURRENT_SOURCE_DIR}/cdrom_boot.cnf ${CDROM_DATA} VERBATIM)
add_custom_target(cdboot_test_disc ALL DEPENDS ${CMAKE_CURRENT_BINARY_DIR}/cdboot_test.cue)
# CHECKS: disc_check.c's CHECK_EQ call sites, each run once.
psx_add_run_test(rom.cdboot_disc_check CODE 0 CHECKS 9
  OUTPUT "cdboot: psxrl disc boot ROM\ncdboot: GPU in 480-line interlace, fields followed\ncdboot: SYSTEM.CNF BOOT=\\BOOT.EXE"
  RUN --bios ${CDBOOT_ROM} --disc ${CMAKE_CURRENT_BINARY_DIR}/cdboot_test.cue --frames 600 --expect-exit)

# The disc the HLE fast boot test uses boots through the ROM as well (cdrom_boot.c: 1 check).
psx_add_run_test(rom.cdboot_hle_disc CODE 0 CHECKS 1 OUTPUT "booted from disc"
  RUN --bios ${CDBOOT_ROM} --disc ${CMAKE_CURRENT_BINARY_DIR}/cdrom_boot.cue --frames 600 --expect-exit)

# A disc without SYSTEM.CNF or PSX.EXE: the ROM reports it and stops with code 3.
add_test(NAME rom.cdboot_no_exe
  COMMAND ${CMAKE_COMMAND} -DEXPECT_CODE=3 "-DEXPECT_OUTPUT=cdboot: PSX.EXE"
          -DCOMMAND=$<TARGET_FILE:psxrl>|run|--bios|${CDBOOT_ROM}|--disc|${CMAKE_CURRENT_BINARY_DIR}/cdrom_test.cue|--frames|600|--expect-exit
          -P ${PROJECT_SOURCE_DIR}/tests/expect.cmake)

# Tumble's disc through the ROM from the command line: a pure low-level boot (the ROM reads the
# disc; no HLE, nothing side-loaded). tests/unit/cdboot_bios_boot_test.cpp checks it reaches its title.
add_test(NAME rom.cdboot_tumble_disc
  COMMAND ${CMAKE_COMMAND} -DEXPECT_CODE=0 "-DEXPECT_OUTPUT=cdboot: loading \\TUMBLE.EXE"
          -DCOMMAND=$<TARGET_FILE:psxrl>|run|--bios|${CDBOOT_ROM}|--disc|${PROJECT_BINARY_DIR}/games/tumble/tumble.cue|--frames|120
          -P ${PROJECT_SOURCE_DIR}/tests/expect.cmake)

# `psxrl run --bios B` with no EXE and no disc starts the BIOS alone: the ROM finds the drive empty
# and idles as a BIOS shell would, so the run ends at its frame limit with exit code 0.
add_test(NAME rom.cdboot_bios_alone
  COMMAND ${CMAKE_COMMAND} -DEXPECT_CODE=0 "-DEXPECT_OUTPUT=cdboot: no disc: shell idle"
          -DCOMMAND=$<TARGET_FILE:psxrl>|run|--bios|${CDBOOT_ROM}|--frames|60
          -P ${PROJECT_SOURCE_DIR}/tests/expect.cmake)
