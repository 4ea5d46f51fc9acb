/* B(51h) Krom2RawAdd and the kanji font in ROM (psx-spx "BIOS Character Sets"): codes 8140h-84BEh
   are charset 2 at BFC66000h, 889Fh-9872h charset 3 at BFC69D68h, 16x15 pixels in 30 bytes (two
   bytes a row, leftmost pixel in bit 7 of the first), charset 4 starting at BFC7F8DEh; other
   codes give -1. bios_font_rows.h (tests/bdf_glyph_rows.cmake) holds each code's address and
   rows as computed from the font's BDF. */
#include "bios_calls.h"
#include "bios_font_rows.h"
#include "psx/test.h"

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Rows of the glyph at `address` that differ from `rows`, one bit each. */
static uint32_t differing_rows(uint32_t address, const uint16_t *rows) {
  const volatile uint8_t *p = (const volatile uint8_t *)address;
  uint32_t bad = 0;
  for (uint32_t y = 0; y < 15; ++y)
    if ((uint16_t)(p[2 * y] << 8 | p[2 * y + 1]) != rows[y]) bad |= 1u << y;
  return bad;
}

int main(void) {
  for (uint32_t i = 0; i < COUNT(expected_glyphs); ++i) {
    uint32_t address = (uint32_t)krom2_raw_add(expected_glyphs[i].sjis);
    if (address != expected_glyphs[i].address) tty_printf("Krom2RawAdd(%04x):\n", expected_glyphs[i].sjis);
    CHECK_EQ("glyph address", address, expected_glyphs[i].address);
    CHECK_EQ("glyph rows", differing_rows(address, expected_glyphs[i].rows), 0);
  }
  /* 524 glyphs fill charset 2 up to charset 3, 2965 charset 3 up to charset 4. */
  CHECK_EQ("84BEh is charset 2's last glyph", (uint32_t)krom2_raw_add(0x84BE) + 30, 0xBFC69D68);
  CHECK_EQ("9872h is charset 3's last glyph", (uint32_t)krom2_raw_add(0x9872) + 30, 0xBFC7F8DE);
  CHECK_EQ("0041h (single byte) has no glyph", krom2_raw_add(0x0041), -1);
  CHECK_EQ("813Fh (before charset 2) has no glyph", krom2_raw_add(0x813F), -1);
  CHECK_EQ("84BFh (after charset 2) has no glyph", krom2_raw_add(0x84BF), -1);
  CHECK_EQ("889Eh (before charset 3) has no glyph", krom2_raw_add(0x889E), -1);
  CHECK_EQ("9873h (after charset 3) has no glyph", krom2_raw_add(0x9873), -1);
  CHECK_EQ("FFFFh has no glyph", krom2_raw_add(0xFFFF), -1);
  return test_done("bios_font");
}
