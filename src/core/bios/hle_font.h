// The HLE kernel's ROM kanji font (psx-spx "BIOS Character Sets"): the glyphs a BIOS keeps at
// BFC66000h (charset 2, Shift-JIS 8140h-84BEh) and BFC69D68h (charset 3, 889Fh-9872h), 16x15
// pixels in 30 bytes each, and B(51h) Krom2RawAdd's lookup. The glyphs are Debian's public-domain
// Shinonome 14-dot font, converted at build time by tools/krom_font (the generated source
// defines kCodes and kGlyphs), as OpenBIOS ships the same font in the same layout.
#pragma once
#include "core/types.h"

namespace psx::krom {

constexpr u32 kGlyphBytes = 30;
constexpr u32 kCharset2 = 0xBFC66000, kCharset3 = 0xBFC69D68;

// The font's glyph counts, the Shift-JIS code of each glyph (charset 2's, then charset 3's, in
// ascending order) and their bitmaps in the same order (generated).
extern const u32 kCharset2Glyphs, kCharset3Glyphs;
extern const u16 kCodes[];
extern const u8 kGlyphs[];

// Writes the two charsets into a 512 KiB ROM image at their addresses.
void map(u8* rom);
// Krom2RawAdd: the ROM address of a code's glyph, or FFFFFFFFh outside the two charsets.
u32 raw_add(u32 code);

}  // namespace psx::krom
