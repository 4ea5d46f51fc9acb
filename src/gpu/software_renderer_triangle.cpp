// Software rasterizer: triangles (GP0(20)-(3F); a quad arrives as two triangles).
// Rules (psx-spx "GPU Rendering"): a pixel (x, y) is drawn when the exact edge positions on row y
// satisfy left <= x < right and the row lies in top <= y < bottom (top-left fill rule: right and
// bottom edges are left out, so quads sharing an edge never overlap). Colours and texture
// coordinates are affine planes over the screen, stepped with 12 fraction bits and a half-unit
// bias at the top vertex like the hardware's interpolators; no perspective correction.
#include <emmintrin.h>  // SSE2, part of x86-64 (the recompiler already requires that host)

#include <algorithm>
#include <cstring>
#include <utility>

#include "gpu/software_renderer.h"
#include "gpu/software_renderer_pixel.h"
#include "gpu/triangle_setup.h"

namespace psx::gpu {
namespace {

// An attribute's value at (x, y): the top vertex's value plus half a unit, stepped by the plane.
inline s32 attribute_at(s32 base, const Gradient& g, s32 dx, s32 dy) {
  return static_cast<s32>((s64{base} << kFrac) + (1 << (kFrac - 1)) + s64{g.dx} * dx + s64{g.dy} * dy);
}

inline u32 channel(s32 fixed) { return static_cast<u32>(std::clamp(fixed >> kFrac, 0, 255)); }

// The dither offsets (kDitherMatrix) of eight pixels in a row from x: [y & 3][x & 3][lane].
struct DitherLanes {
  alignas(16) s16 v[4][4][8];
};
constexpr DitherLanes make_dither_lanes() {
  DitherLanes t{};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int i = 0; i < 8; ++i) t.v[y][x][i] = kDitherMatrix[y][(x + i) & 3];
  return t;
}
inline constexpr DitherLanes kDitherLanes = make_dither_lanes();

// channel() then dither_to_5() on eight pixels: clamp(clamp(v >> 12, 0, 255) + dither, 0, 255)
// >> 3. Packing to 16 bits saturates, which leaves the clamp to 0..255 unchanged.
inline __m128i channel5(__m128i lo, __m128i hi, __m128i dither) {
  const __m128i zero = _mm_setzero_si128(), top = _mm_set1_epi16(255);
  __m128i c = _mm_packs_epi32(_mm_srai_epi32(lo, kFrac), _mm_srai_epi32(hi, kFrac));
  c = _mm_min_epi16(_mm_max_epi16(c, zero), top);
  c = _mm_min_epi16(_mm_max_epi16(_mm_add_epi16(c, dither), zero), top);
  return _mm_srli_epi16(c, 3);
}

// Rows of an opaque untextured polygon (flat or Gouraud), eight pixels per step: the pixels that
// draw_pixel<kUntextured, false, false> gives one by one, mask check and dither included. A
// channel's eight lanes hold value + i * step, wrapping in 32 bits as per-pixel additions do.
class ColourRows {
 public:
  // Steps per pixel of the 12-bit fixed-point red, green and blue (0 for a flat polygon).
  ColourRows(const PixelContext& c, s32 dr, s32 dg, s32 db)
      : ctx_(c), mask_or_(_mm_set1_epi16(static_cast<s16>(c.mask_or))) {
    const s32 steps[3] = {dr, dg, db};
    for (int k = 0; k < 3; ++k) {
      const auto at = [&](u32 i) { return static_cast<s32>(i * static_cast<u32>(steps[k])); };
      offset_lo_[k] = _mm_setr_epi32(at(0), at(1), at(2), at(3));
      offset_hi_[k] = _mm_setr_epi32(at(4), at(5), at(6), at(7));
      step8_[k] = _mm_set1_epi32(at(8));
    }
  }

  // `count` pixels of row y from column x, whose first pixel has the channels r, g, b.
  void draw(s32 x, s32 y, u32 count, s32 r, s32 g, s32 b) const {
    const __m128i dither = ctx_.dither ? load(kDitherLanes.v[y & 3][x & 3]) : _mm_setzero_si128();
    __m128i lo[3], hi[3];
    const s32 first[3] = {r, g, b};
    for (int k = 0; k < 3; ++k) {
      lo[k] = _mm_add_epi32(_mm_set1_epi32(first[k]), offset_lo_[k]);
      hi[k] = _mm_add_epi32(_mm_set1_epi32(first[k]), offset_hi_[k]);
    }
    u16* dst = ctx_.vram + static_cast<u32>(y) * kVramWidth + static_cast<u32>(x);
    const u32 room = kVramWidth - static_cast<u32>(x);  // pixels to the end of the VRAM row
    for (u32 i = 0; i < count; i += 8) {
      const __m128i out = _mm_or_si128(
          _mm_or_si128(channel5(lo[0], hi[0], dither), _mm_slli_epi16(channel5(lo[1], hi[1], dither), 5)),
          _mm_or_si128(_mm_slli_epi16(channel5(lo[2], hi[2], dither), 10), mask_or_));
      store(dst + i, out, std::min(count - i, 8u), room - i);
      for (int k = 0; k < 3; ++k) lo[k] = _mm_add_epi32(lo[k], step8_[k]), hi[k] = _mm_add_epi32(hi[k], step8_[k]);
    }
  }

 private:
  static __m128i load(const void* p) { return _mm_loadu_si128(static_cast<const __m128i*>(p)); }

  // Writes the first n of eight pixels where the mask check allows. Lanes past n keep the
  // pixels there; past the end of the VRAM row (room < 8) the pixels go through a copy.
  void store(u16* dst, __m128i out, u32 n, u32 room) const {
    u16 part[8] = {};
    u16* at = room >= 8 ? dst : part;
    if (room < 8) std::memcpy(part, dst, n * sizeof(u16));
    const __m128i old = load(at);
    __m128i keep = _mm_cmplt_epi16(_mm_set_epi16(7, 6, 5, 4, 3, 2, 1, 0), _mm_set1_epi16(static_cast<s16>(n)));
    keep = _mm_xor_si128(keep, _mm_set1_epi16(-1));  // all ones in lanes to leave as they are
    if (ctx_.check_mask) keep = _mm_or_si128(keep, _mm_srai_epi16(old, 15));  // bit 15 set: kept
    _mm_storeu_si128(reinterpret_cast<__m128i*>(at), _mm_or_si128(_mm_and_si128(keep, old), _mm_andnot_si128(keep, out)));
    if (room < 8) std::memcpy(dst, part, n * sizeof(u16));
  }

  const PixelContext& ctx_;
  __m128i mask_or_;
  __m128i offset_lo_[3], offset_hi_[3], step8_[3];
};

}  // namespace

template <int kTex, bool kRaw, bool kSemi, bool kShaded>
void SoftwareRenderer::rasterize_triangle(const Triangle& t, const DrawState& ds) {
  const SortedTriangle sorted = sort_by_y(t);
  const Vertex* const* p = sorted.p;
  const s64 cross = sorted.cross;
  const Vertex &a = *p[0], &b = *p[1], &c = *p[2];
  if (cross == 0) return;  // degenerate: no area, nothing drawn

  constexpr bool kModulated = kTex == kUntextured || !kRaw;
  constexpr bool kGouraud = kShaded && kModulated;
  Gradient gr, gg, gb, gu, gv;
  if constexpr (kGouraud) {
    gr = plane_gradient(p, cross, a.r, b.r, c.r);
    gg = plane_gradient(p, cross, a.g, b.g, c.g);
    gb = plane_gradient(p, cross, a.b, b.b, c.b);
  }
  if constexpr (kTex != kUntextured) {
    gu = plane_gradient(p, cross, a.u, b.u, c.u);
    gv = plane_gradient(p, cross, a.v, b.v, c.v);
  }

  // Dither applies to Gouraud-shaded and texture-modulated polygons (psx-spx GP0(E1).9).
  PixelContext ctx(vram_.data(), ds, t.clut_x, t.clut_y, kGouraud || (kTex != kUntextured && !kRaw));
  s32 y_begin = std::max(a.y, ds.area_top);
  s32 y_end = std::min(c.y - 1, ds.area_bottom);
  if (y_begin > y_end) return;
  SpanWalk span(sorted, y_begin);
  const ColourRows colour_rows(ctx, gr.dx, gg.dx, gb.dx);
  for (s32 y = y_begin; y <= y_end; ++y, span.next_row()) {
    if ((y & 1) == ds.skip_row_parity) continue;
    const s32 x_left = std::max(span.left(), ds.area_left);
    const s32 x_right = std::min(span.right(), ds.area_right);
    if (x_left > x_right) continue;

    s32 dx = x_left - a.x, dy = y - a.y;
    s32 r = 0, g = 0, bl = 0, u = 0, v = 0;
    u32 r8 = t.v[0].r, g8 = t.v[0].g, b8 = t.v[0].b;
    if constexpr (kGouraud) {
      r = attribute_at(a.r, gr, dx, dy);
      g = attribute_at(a.g, gg, dx, dy);
      bl = attribute_at(a.b, gb, dx, dy);
    }
    if constexpr (kTex != kUntextured) {
      u = attribute_at(a.u, gu, dx, dy);
      v = attribute_at(a.v, gv, dx, dy);
    }
    if constexpr (kTex == kUntextured && !kSemi) {
      const u32 count = static_cast<u32>(x_right - x_left + 1);
      if constexpr (kGouraud) colour_rows.draw(x_left, y, count, r, g, bl);
      else colour_rows.draw(x_left, y, count, s32(r8 << kFrac), s32(g8 << kFrac), s32(b8 << kFrac));
      continue;
    }
    const s8* dither = ctx.dither_row(y);
    for (s32 x = x_left; x <= x_right; ++x) {
      if constexpr (kGouraud) {
        r8 = channel(r), g8 = channel(g), b8 = channel(bl);
        r += gr.dx, g += gg.dx, bl += gb.dx;
      }
      u32 tu = 0, tv = 0;
      if constexpr (kTex != kUntextured) {
        tu = static_cast<u32>(u >> kFrac) & 0xFF, tv = static_cast<u32>(v >> kFrac) & 0xFF;
        u += gu.dx, v += gv.dx;
      }
      draw_pixel<kTex, kRaw, kSemi>(ctx, x, y, r8, g8, b8, tu, tv, dither[x & 3]);
    }
  }
}

// Flat triangles take their colour from the first vertex of the command (Triangle::v[0]).
void SoftwareRenderer::draw_triangle(const Triangle& t, const DrawState& ds) {
  // Primitives spanning 1024 or more columns or 512 or more rows are not drawn (psx-spx).
  s32 min_x = std::min({t.v[0].x, t.v[1].x, t.v[2].x}), max_x = std::max({t.v[0].x, t.v[1].x, t.v[2].x});
  s32 min_y = std::min({t.v[0].y, t.v[1].y, t.v[2].y}), max_y = std::max({t.v[0].y, t.v[1].y, t.v[2].y});
  if (max_x - min_x >= 1024 || max_y - min_y >= 512) return;
  if (max_x < ds.area_left || min_x > ds.area_right || max_y < ds.area_top || min_y > ds.area_bottom) return;

  int tex = (t.textured && !ds.texture_disable) ? std::min(ds.tex_depth + 1, 3) : 0;
  switch (tex) {
    case kUntextured: return triangle_modes<kUntextured, false>(t, ds);
    case kClut4: return t.raw ? triangle_modes<kClut4, true>(t, ds) : triangle_modes<kClut4, false>(t, ds);
    case kClut8: return t.raw ? triangle_modes<kClut8, true>(t, ds) : triangle_modes<kClut8, false>(t, ds);
    default: return t.raw ? triangle_modes<kDirect15, true>(t, ds) : triangle_modes<kDirect15, false>(t, ds);
  }
}

// Picks the instantiation for the semi-transparency and shading flags (raw texels ignore shading).
template <int kTex, bool kRaw>
void SoftwareRenderer::triangle_modes(const Triangle& t, const DrawState& ds) {
  constexpr bool kCanShade = kTex == kUntextured || !kRaw;
  if (t.semi) {
    if (kCanShade && t.shaded) return rasterize_triangle<kTex, kRaw, true, kCanShade>(t, ds);
    return rasterize_triangle<kTex, kRaw, true, false>(t, ds);
  }
  if (kCanShade && t.shaded) return rasterize_triangle<kTex, kRaw, false, kCanShade>(t, ds);
  return rasterize_triangle<kTex, kRaw, false, false>(t, ds);
}

}  // namespace psx::gpu
