// Software rasterizer: lines (GP0(40)-(5F)) and rectangles (GP0(60)-(7F)).
// Lines include both end points and are drawn from the left end point whatever the vertex order,
// one pixel along the major axis per step; the minor axis takes the pixel nearest the exact line,
// and where the line passes midway between two, x takes the left one and y the one toward the
// right end point's y (the rule ps1-tests' gpu/lines captures and Mednafen agree on). Colours
// advance by a 12-bit fixed-point fraction with a half-unit bias, and are dithered when E1.9 is
// set, flat or not. Rectangles are never dithered; textured ones step the texture coordinate by one texel per
// pixel, backwards when GP0(E1) bits 12/13 flip them.
#include <algorithm>
#include <cstdlib>

#include "gpu/software_renderer.h"
#include "gpu/software_renderer_pixel.h"

namespace psx::gpu {

namespace {
// One coordinate of a line's pixels: start + |delta| * i / steps rounded to the nearest integer,
// exact halves toward the end point or toward the start. An error term, 2|delta|i + steps
// (- 1 to round halves toward the start) - 2 steps * offset, kept in [0, 2 steps), makes that
// exact for any length, where a fixed-point step would drift off the halves.
struct LineAxis {
  s32 pos, dir, error, add, wrap;
  LineAxis(s32 start, s32 delta, s32 steps, bool halves_to_end)
      : pos(start),
        dir(delta < 0 ? -1 : 1),
        error(halves_to_end ? steps : steps - 1),
        add(2 * std::abs(delta)),
        wrap(2 * steps) {}
  // |delta| <= steps, so one step moves the coordinate by at most one pixel.
  void step() {
    error += add;
    if (error >= wrap) error -= wrap, pos += dir;
  }
};
}  // namespace

template <int kTex, bool kRaw, bool kSemi>
void SoftwareRenderer::rasterize_rectangle(const Rectangle& r, const DrawState& ds) {
  PixelContext ctx(vram_.data(), ds, clut_, false);
  s32 y_begin = std::max(r.y, ds.area_top), y_end = std::min(r.y + static_cast<s32>(r.height) - 1, ds.area_bottom);
  s32 x_begin = std::max(r.x, ds.area_left), x_end = std::min(r.x + static_cast<s32>(r.width) - 1, ds.area_right);
  const s32 du = ds.flip_x ? -1 : 1, dv = ds.flip_y ? -1 : 1;
  for (s32 y = y_begin; y <= y_end; ++y) {
    if ((y & 1) == ds.skip_row_parity) continue;
    u32 v = static_cast<u32>(r.v + dv * (y - r.y)) & 0xFF;
    u32 u = static_cast<u32>(r.u + du * (x_begin - r.x));
    for (s32 x = x_begin; x <= x_end; ++x, u += du)
      draw_pixel<kTex, kRaw, kSemi>(ctx, x, y, r.r, r.g, r.b, u & 0xFF, v, 0);
  }
}

void SoftwareRenderer::draw_rectangle(const Rectangle& r, const DrawState& ds) {
  if (r.width == 0 || r.height == 0) return;
  int tex = (r.textured && !ds.texture_disable) ? std::min(ds.tex_depth + 1, 3) : 0;
  const bool raw = r.raw, semi = r.semi;
  switch (tex) {
    case kUntextured:
      return semi ? rasterize_rectangle<kUntextured, false, true>(r, ds)
                  : rasterize_rectangle<kUntextured, false, false>(r, ds);
    case kClut4:
      if (raw) return semi ? rasterize_rectangle<kClut4, true, true>(r, ds) : rasterize_rectangle<kClut4, true, false>(r, ds);
      return semi ? rasterize_rectangle<kClut4, false, true>(r, ds) : rasterize_rectangle<kClut4, false, false>(r, ds);
    case kClut8:
      if (raw) return semi ? rasterize_rectangle<kClut8, true, true>(r, ds) : rasterize_rectangle<kClut8, true, false>(r, ds);
      return semi ? rasterize_rectangle<kClut8, false, true>(r, ds) : rasterize_rectangle<kClut8, false, false>(r, ds);
    default:
      if (raw)
        return semi ? rasterize_rectangle<kDirect15, true, true>(r, ds) : rasterize_rectangle<kDirect15, true, false>(r, ds);
      return semi ? rasterize_rectangle<kDirect15, false, true>(r, ds)
                  : rasterize_rectangle<kDirect15, false, false>(r, ds);
  }
}

template <bool kSemi, bool kShaded>
void SoftwareRenderer::rasterize_line(const Line& l, const DrawState& ds) {
  // Drawn from the left end point: (10,0)->(0,3) is the line (0,3)->(10,0).
  const bool swap = l.v[0].x > l.v[1].x;
  const Vertex &p0 = l.v[swap ? 1 : 0], &p1 = l.v[swap ? 0 : 1];
  s32 dx = p1.x - p0.x, dy = p1.y - p0.y;
  s32 steps = std::max(std::abs(dx), std::abs(dy));
  // Lines are dithered whenever GP0(E1).9 is set, flat ones too (ps1-tests gpu/lines captures:
  // flat 0xAA lines come out 20 and 21 in the dither pattern).
  PixelContext ctx(vram_.data(), ds, clut_, true);

  // At an exact half step x rounds down (toward the start) and y toward the right end point.
  LineAxis x(p0.x, dx, steps, false), y(p0.y, dy, steps, true);
  // Colours in 12-bit fixed point with a half-unit bias.
  s32 r = (p0.r << 12) + 2048, g = (p0.g << 12) + 2048, b = (p0.b << 12) + 2048;
  s32 step_r = 0, step_g = 0, step_b = 0;
  if (kShaded && steps) {
    step_r = ((p1.r - p0.r) << 12) / steps, step_g = ((p1.g - p0.g) << 12) / steps;
    step_b = ((p1.b - p0.b) << 12) / steps;
  }
  for (s32 i = 0; i <= steps; ++i) {
    const s32 px = x.pos, py = y.pos;
    if (px >= ds.area_left && px <= ds.area_right && py >= ds.area_top && py <= ds.area_bottom &&
        (py & 1) != ds.skip_row_parity)
      draw_pixel<kUntextured, false, kSemi>(ctx, px, py, static_cast<u32>(r >> 12), static_cast<u32>(g >> 12),
                                            static_cast<u32>(b >> 12), 0, 0, ctx.dither_row(py)[px & 3]);
    x.step(), y.step();
    r += step_r, g += step_g, b += step_b;
  }
}

void SoftwareRenderer::draw_line(const Line& l, const DrawState& ds) {
  // Lines spanning 1024 or more columns or 512 or more rows are not drawn (psx-spx).
  if (std::abs(l.v[1].x - l.v[0].x) >= 1024 || std::abs(l.v[1].y - l.v[0].y) >= 512) return;
  if (l.semi) return l.shaded ? rasterize_line<true, true>(l, ds) : rasterize_line<true, false>(l, ds);
  return l.shaded ? rasterize_line<false, true>(l, ds) : rasterize_line<false, false>(l, ds);
}

}  // namespace psx::gpu
