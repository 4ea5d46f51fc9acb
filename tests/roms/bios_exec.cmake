# LoadTest/Load/Exec/LoadExec/_boot (bios_exec.c): a mkdisc disc with the test as BOOT.EXE, its
# child program as CHILD.EXE (linked at 0x80100000, no start-up code: Exec/LoadExec start it) and
# cdrom.cmake's DATA.BIN as a file that is no executable. The parent runs 20 checks, then LoadExec
# hands over to the child, which adds 5 and prints the total. A second disc boots a program that
# LoadExecs DATA.BIN: the run stops (exit 3) with "LoadExec cannot start cdrom:\DATA.BIN;1: offset
# 0: expected the magic ..." (the test looks for its end: ';' and '\' do not survive CTest's
# argument passing).
psx_add_exe(bios_exec SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bios_exec.c ${CMAKE_CURRENT_SOURCE_DIR}/bios_exec_calls.S
            ${CMAKE_CURRENT_SOURCE_DIR}/bios_file_calls.S ${CMAKE_CURRENT_SOURCE_DIR}/bios_calls.S)
psx_add_exe(bios_exec_child NO_RUNTIME LINKER_SCRIPT ${CMAKE_CURRENT_SOURCE_DIR}/bios_exec_child.ld
            SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bios_exec_child_start.S ${CMAKE_CURRENT_SOURCE_DIR}/bios_exec_child.c
                    ${PSX_GUEST_DIR}/runtime.c)
psx_add_exe(bios_exec_bad SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bios_exec_bad.c ${CMAKE_CURRENT_SOURCE_DIR}/bios_exec_calls.S)
foreach(disc bios_exec bios_exec_bad)
  add_custom_command(OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/${disc}.cue ${CMAKE_CURRENT_BINARY_DIR}/${disc}.bin
    COMMAND mkdisc -o ${CMAKE_CURRENT_BINARY_DIR}/${disc}.cue --exe ${CMAKE_CURRENT_BINARY_DIR}/${disc}.exe
            --exe-name BOOT.EXE --cnf ${CMAKE_CURRENT_SOURCE_DIR}/cdrom_boot.cnf
            ${CMAKE_CURRENT_BINARY_DIR}/bios_exec_child.exe=CHILD.EXE ${CMAKE_CURRENT_BINARY_DIR}/cdrom_data.bin=DATA.BIN
    DEPENDS mkdisc ${disc} bios_exec_child ${CMAKE_CURRENT_BINARY_DIR}/${disc}.exe
            ${CMAKE_CURRENT_BINARY_DIR}/bios_exec_child.exe ${CMAKE_CURRENT_BINARY_DIR}/cdrom_data.bin ${CMAKE_CURRENT_SOURCE_DIR}/cdrom_boot.cnf
    VERBATIM)
  add_custom_target(${disc}_disc ALL DEPENDS ${CMAKE_CURRENT_BINARY_DIR}/${disc}.cue)
endforeach()
psx_add_run_test(rom.bios_exec CODE 0 CHECKS 25
  RUN --disc ${CMAKE_CURRENT_BINARY_DIR}/bios_exec.cue --frames 600 --expect-exit)
psx_add_run_test(rom.bios_exec_bad CODE 3 OUTPUT "offset 0: expected the magic"
  RUN --disc ${CMAKE_CURRENT_BINARY_DIR}/bios_exec_bad.cue --frames 600 --expect-exit)
