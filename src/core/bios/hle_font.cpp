// The HLE kernel's ROM kanji font: the charsets' place in the ROM and Krom2RawAdd (hle_font.h).
#include "core/bios/hle_font.h"

#include <algorithm>
#include <cstring>

namespace psx::krom {

namespace {
constexpr u32 kRomBase = 0xBFC00000;
}

void map(u8* rom) {
  std::memcpy(rom + (kCharset2 - kRomBase), kGlyphs, kCharset2Glyphs * kGlyphBytes);
  std::memcpy(rom + (kCharset3 - kRomBase), kGlyphs + kCharset2Glyphs * kGlyphBytes, kCharset3Glyphs * kGlyphBytes);
}

// psx-spx: the code should be 8140h-84BEh (charset 2) or 889Fh-9872h (charset 3), else -1. Only
// its low 16 bits count (OpenBIOS's sjis.h: GT2 passes sign-extended 16-bit codes, and masks them
// as the BIOS must). The BIOS finds the code's run of consecutive assigned codes in a table of
// (first code, glyph index) pairs (the table read out of a Sony ROM in pcsx-redux's
// openbios/charset/sjis.c); a code between runs continues the run before it, as here.
u32 raw_add(u32 code) {
  code &= 0xFFFF;
  const u16* first;
  const u16* last;
  u32 base;
  if (code >= 0x8140 && code <= 0x84BE) {
    first = kCodes, last = kCodes + kCharset2Glyphs, base = kCharset2;
  } else if (code >= 0x889F && code <= 0x9872) {
    first = kCodes + kCharset2Glyphs, last = first + kCharset3Glyphs, base = kCharset3;
  } else {
    return 0xFFFFFFFF;
  }
  const u16* run = std::upper_bound(first, last, code);
  if (run == first) return 0xFFFFFFFF;
  --run;
  return base + (static_cast<u32>(run - first) + (code - *run)) * kGlyphBytes;
}

}  // namespace psx::krom
