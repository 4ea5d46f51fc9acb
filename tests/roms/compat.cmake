# Programs for psxrl compat's tests (tests/unit/cli_compat_test.cpp): a picture known by
# construction, as an EXE and on a disc made by mkdisc, a program that calls a BIOS function no
# kernel implements, and a picture that changes at every VBlank.
psx_add_exe(compat_picture SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/compat_picture.c)
psx_add_exe(compat_unsupported SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/compat_unsupported.S)
psx_add_exe(compat_frames SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/compat_frames.c)
add_custom_command(OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/compat_picture.cue ${CMAKE_CURRENT_BINARY_DIR}/compat_picture.bin
  COMMAND mkdisc -o ${CMAKE_CURRENT_BINARY_DIR}/compat_picture.cue --exe ${CMAKE_CURRENT_BINARY_DIR}/compat_picture.exe
          --exe-name BOOT.EXE --cnf ${CMAKE_CURRENT_SOURCE_DIR}/cdrom_boot.cnf
  DEPENDS mkdisc compat_picture ${CMAKE_CURRENT_BINARY_DIR}/compat_picture.exe
          ${CMAKE_CURRENT_SOURCE_DIR}/cdrom_boot.cnf VERBATIM)
add_custom_target(compat_picture_disc ALL DEPENDS ${CMAKE_CURRENT_BINARY_DIR}/compat_picture.cue)
