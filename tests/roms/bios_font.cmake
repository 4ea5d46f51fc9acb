# B(51h) Krom2RawAdd and the ROM kanji font under the HLE kernel (tests/roms/bios_font.c). The
# expected addresses and glyph rows come from the font's BDF form, read by the test harness
# (tests/bdf_glyph_rows.cmake), not from the kernel's converter (tools/krom_font).
find_program(PCF2BDF pcf2bdf)
if(NOT PCF2BDF)
  message(FATAL_ERROR "rom.bios_font needs pcf2bdf to read the kanji font's glyphs: install Debian's pcf2bdf "
                      "(scripts/setup.sh does)")
endif()
# First and last codes of each charset, and codes of each JIS row group psyqo's fonts and games
# use: punctuation, digits, Latin, hiragana, katakana, Greek, Cyrillic, box drawing, kanji.
set(font_codes 8140 8148 81B8 824F 8260 8281 82A0 8340 839F 8440 84BE 889F 88A0 9340 9872)
set(font_rows ${CMAKE_CURRENT_BINARY_DIR}/bios_font_rows.h)
add_custom_command(OUTPUT ${font_rows}
  COMMAND ${CMAKE_COMMAND} -DPCF2BDF=${PCF2BDF} -DFONT=${PSXRL_KANJI_FONT} "-DCODES=${font_codes}"
          -DOUT=${font_rows} -P ${PROJECT_SOURCE_DIR}/tests/bdf_glyph_rows.cmake
  DEPENDS ${PROJECT_SOURCE_DIR}/tests/bdf_glyph_rows.cmake ${PSXRL_KANJI_FONT} VERBATIM)
psx_add_exe(bios_font SOURCES ${CMAKE_CURRENT_SOURCE_DIR}/bios_font.c ${CMAKE_CURRENT_SOURCE_DIR}/bios_calls.S
  INCLUDES ${CMAKE_CURRENT_BINARY_DIR} DEPENDS ${font_rows})
# CHECKS: 2 a code for the 15 codes above (address, rows), 2 charset ends, 6 codes with no glyph.
psx_add_run_test(rom.bios_font CODE 0 CHECKS 38
  RUN --exe ${CMAKE_CURRENT_BINARY_DIR}/bios_font.exe --frames 600 --expect-exit)
