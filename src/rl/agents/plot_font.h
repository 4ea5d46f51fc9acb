// A 5x7 bitmap font for the learning curve's labels (digits, capitals and a few signs), the
// glyphs of Tumble's built-in font (games/tumble/tools/fontgen.c), so plots need no font library.
#pragma once

namespace psxrl::agents {

inline constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6;

// 35 characters, 7 rows of 5 columns, '#' for ink; nullptr for a character without a glyph
// (drawn blank, as a space).
const char* glyph(char c);

}  // namespace psxrl::agents
