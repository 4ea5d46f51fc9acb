// Software rasterizer: triangles (GP0(20)-(3F); a quad arrives as two triangles).
// Rules (psx-spx "GPU Rendering"): a pixel (x, y) is drawn when the exact edge positions on row y
// satisfy left <= x < right and the row lies in top <= y < bottom (top-left fill rule: right and
// bottom edges are left out, so quads sharing an edge never overlap). Colours and texture
// coordinates are affine planes over the screen, stepped with 12 fraction bits (gradients
// truncated) and a half-unit bias at the leftmost vertex like the hardware's interpolators; no
// perspective correction.
#include <algorithm>
#include <utility>

#include "gpu/software_renderer.h"
#include "gpu/software_renderer_pixel.h"
#include "gpu/software_renderer_rows.h"
#include "gpu/triangle_setup.h"

namespace psx::gpu {
namespace {

// An attribute's value at (x, y): the core vertex's value (core_vertex(), triangle_setup.h) plus
// half a unit, stepped by the plane; dx and dy are measured from that vertex.
inline s32 attribute_at(s32 base, const Gradient& g, s32 dx, s32 dy) {
  return static_cast<s32>((s64{base} << kFrac) + (1 << (kFrac - 1)) + s64{g.dx} * dx + s64{g.dy} * dy);
}

inline u32 channel(s32 fixed) { return static_cast<u32>(std::clamp(fixed >> kFrac, 0, 255)); }

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
  PixelContext ctx(vram_.data(), ds, clut_, kGouraud || (kTex != kUntextured && !kRaw));
  s32 y_begin = std::max(a.y, ds.area_top);
  s32 y_end = std::min(c.y - 1, ds.area_bottom);
  if (y_begin > y_end) return;
  SpanWalk span(sorted, y_begin);
  const Vertex& o = core_vertex(t);
  const RowPainter rows(ctx, gr.dx, gg.dx, gb.dx);
  for (s32 y = y_begin; y <= y_end; ++y, span.next_row()) {
    if ((y & 1) == ds.skip_row_parity) continue;
    const s32 x_left = std::max(span.left(), ds.area_left);
    const s32 x_right = std::min(span.right(), ds.area_right);
    if (x_left > x_right) continue;

    s32 dx = x_left - o.x, dy = y - o.y;
    s32 r = 0, g = 0, bl = 0, u = 0, v = 0;
    u32 r8 = t.v[0].r, g8 = t.v[0].g, b8 = t.v[0].b;
    if constexpr (kGouraud) {
      r = attribute_at(o.r, gr, dx, dy);
      g = attribute_at(o.g, gg, dx, dy);
      bl = attribute_at(o.b, gb, dx, dy);
    }
    if constexpr (kTex != kUntextured) {
      u = attribute_at(o.u, gu, dx, dy);
      v = attribute_at(o.v, gv, dx, dy);
    }
    if constexpr (!kSemi) {  // opaque: eight pixels at a time
      const u32 count = static_cast<u32>(x_right - x_left + 1);
      if constexpr (!kGouraud) r = s32(r8 << kFrac), g = s32(g8 << kFrac), bl = s32(b8 << kFrac);
      if constexpr (kTex == kUntextured) rows.colour(x_left, y, count, r, g, bl);
      else rows.textured<kTex, kRaw>(x_left, y, count, r, g, bl, u, v, gu.dx, gv.dx);
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
