// The software rasterizer's per-pixel pipeline (psx-spx "GPU Rendering"): texel fetch through
// the texture window and CLUT, modulation colour*texel/128, 4x4 dither, the four
// semi-transparency equations and the mask bit. Everything is inline and chosen by template
// parameters per primitive, so the inner loops carry no per-pixel calls or mode branches that
// a primitive cannot change.
#pragma once
#include <algorithm>

#include "gpu/renderer.h"
#include "gpu/vram.h"

namespace psx::gpu {

// Texture source for one primitive: 0 untextured, 1 4-bit CLUT, 2 8-bit CLUT, 3 15-bit direct.
enum TexMode : int { kUntextured = 0, kClut4 = 1, kClut8 = 2, kDirect15 = 3 };

// The 4x4 dither matrix (psx-spx "Dithering"), indexed [y & 3][x & 3], added to 8-bit channels.
inline constexpr s8 kDitherMatrix[4][4] = {{-4, 0, -3, 1}, {2, -2, 3, -1}, {-3, 1, -4, 0}, {3, -1, 2, -2}};
inline constexpr s8 kNoDither[4] = {0, 0, 0, 0};

// Everything a primitive's pixels share, decoded once per primitive.
struct PixelContext {
  u16* vram = nullptr;
  u32 page_x = 0, page_y = 0;  // texture page base in VRAM pixels
  const u16* clut = nullptr;  // the renderer's CLUT cache (Renderer::load_clut())
  u8 win_and_u = 0xFF, win_or_u = 0, win_and_v = 0xFF, win_or_v = 0;
  u8 semi_mode = 0;
  bool dither = false;
  bool check_mask = false;
  u16 mask_or = 0;

  PixelContext(u16* v, const DrawState& ds, const u16* palette, bool dithered)
      : vram(v), page_x(ds.texpage_x), page_y(ds.texpage_y), clut(palette),
        win_and_u(ds.win_and_u), win_or_u(ds.win_or_u), win_and_v(ds.win_and_v), win_or_v(ds.win_or_v),
        semi_mode(ds.semi_mode), dither(dithered && ds.dither), check_mask(ds.check_mask),
        mask_or(ds.set_mask ? kMaskBit : 0) {}

  const s8* dither_row(s32 y) const { return dither ? kDitherMatrix[y & 3] : kNoDither; }
};

// Texel at texture coordinate (u, v): window applied, then the page lookup with VRAM wrap and
// the CLUT cache's entry.
template <int kTex>
inline u16 fetch_texel(const PixelContext& c, u32 u, u32 v) {
  u = (u & c.win_and_u) | c.win_or_u;
  v = (v & c.win_and_v) | c.win_or_v;
  const u16* row = c.vram + ((c.page_y + v) & (kVramHeight - 1)) * kVramWidth;
  if constexpr (kTex == kClut4) {
    u32 word = row[(c.page_x + (u >> 2)) & (kVramWidth - 1)];
    return c.clut[(word >> ((u & 3) * 4)) & 0xF];
  } else if constexpr (kTex == kClut8) {
    u32 word = row[(c.page_x + (u >> 1)) & (kVramWidth - 1)];
    return c.clut[(word >> ((u & 1) * 8)) & 0xFF];
  } else {
    return row[(c.page_x + u) & (kVramWidth - 1)];
  }
}

// An 8-bit channel value (up to 511 before saturation, from modulation) plus a dither offset
// (-4..+3), saturated to 0..255 and truncated to the 5 bits VRAM keeps: a constant table, so the
// inner loops do one load instead of two clamps per channel.
struct Saturate5Table {
  u8 v[8][512];
};
constexpr Saturate5Table make_saturate5_table() {
  Saturate5Table t{};
  for (int d = -4; d < 4; ++d)
    for (int c = 0; c < 512; ++c) t.v[d + 4][c] = static_cast<u8>(std::clamp(c + d, 0, 255) >> 3);
  return t;
}
inline constexpr Saturate5Table kSaturate5 = make_saturate5_table();

inline u32 dither_to_5(u32 c8, s32 offset) { return kSaturate5.v[offset + 4][c8]; }

// Untextured colour (flat or Gouraud) to a 15-bit pixel.
inline u16 colour_pixel(u32 r8, u32 g8, u32 b8, s32 d) {
  return static_cast<u16>(dither_to_5(r8, d) | (dither_to_5(g8, d) << 5) | (dither_to_5(b8, d) << 10));
}

// Modulation (psx-spx: "colour * texel / 128", 0x80 leaves the texel unchanged), computed in
// 8-bit precision so the dither offset applies before the final truncation; saturates at 31.
inline u16 modulate(u16 texel, u32 r8, u32 g8, u32 b8, s32 d) {
  u32 r = ((texel & 0x1F) * r8) >> 4;  // at most 31 * 255 / 16 = 494: saturated by the table
  u32 g = (((texel >> 5) & 0x1F) * g8) >> 4;
  u32 b = (((texel >> 10) & 0x1F) * b8) >> 4;
  return static_cast<u16>(dither_to_5(r, d) | (dither_to_5(g, d) << 5) | (dither_to_5(b, d) << 10) |
                          (texel & kMaskBit));
}

// Semi-transparency on 5-bit channels, B = background (VRAM), F = foreground (new pixel).
inline u16 blend(u16 back, u16 front, u32 mode) {
  s32 out = 0;
  for (u32 shift = 0; shift < 15; shift += 5) {
    s32 b = (back >> shift) & 0x1F, f = (front >> shift) & 0x1F, c;
    switch (mode) {
      case 0: c = (b + f) >> 1; break;
      case 1: c = std::min(31, b + f); break;
      case 2: c = std::max(0, b - f); break;
      default: c = std::min(31, b + (f >> 2)); break;
    }
    out |= c << shift;
  }
  return static_cast<u16>(out | (front & kMaskBit));
}

// One pixel of a polygon, line or rectangle at (x, y), already clipped to the drawing area.
// Textured: texel 0x0000 is transparent and only texels with bit 15 set are blended.
template <int kTex, bool kRaw, bool kSemi>
inline void draw_pixel(const PixelContext& c, s32 x, s32 y, u32 r8, u32 g8, u32 b8, u32 u, u32 v, s32 d) {
  u16& dst = c.vram[static_cast<u32>(y) * kVramWidth + static_cast<u32>(x)];
  if (c.check_mask && (dst & kMaskBit)) return;
  u16 out;
  bool translucent = kSemi;
  if constexpr (kTex != kUntextured) {
    u16 texel = fetch_texel<kTex>(c, u, v);
    if (texel == 0) return;
    if constexpr (kSemi) translucent = (texel & kMaskBit) != 0;
    if constexpr (kRaw)
      out = texel;
    else
      out = modulate(texel, r8, g8, b8, d);
  } else {
    out = colour_pixel(r8, g8, b8, d);
  }
  if (translucent) out = blend(dst, out, c.semi_mode);
  dst = out | c.mask_or;
}

}  // namespace psx::gpu
