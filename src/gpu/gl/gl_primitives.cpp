// OpenGL renderer: polygons, lines and rectangles become records for the draw program
// (gl_shaders.cpp) with the software renderer's set-up: the same rejection rules, vertex order,
// fixed-point gradients (triangle_setup.h) and dither choice, so that the shader's per-pixel
// arithmetic starts from identical values.
#include <algorithm>
#include <cstdlib>
#include <utility>

#include "gpu/gl/gl_renderer.h"
#include "gpu/triangle_setup.h"

namespace psx::gpu::gl {

namespace {

constexpr s32 kHalf = 1 << (kFrac - 1);

// The drawing state every kind of primitive shares; `tex` is 0 (untextured) to 3 (15-bit).
PrimitiveRecord state_record(Kind kind, const DrawState& ds, int tex, bool raw, bool semi, bool dither) {
  PrimitiveRecord r{};
  u32 f = static_cast<u32>(kind) | static_cast<u32>(tex) << flag::kTexShift;
  if (raw) f |= flag::kRaw;
  if (semi) f |= flag::kSemi | u32{ds.semi_mode} << flag::kSemiModeShift;
  if (dither) f |= flag::kDither;
  if (ds.check_mask) f |= flag::kCheckMask;
  if (ds.set_mask) f |= flag::kSetMask;
  f |= static_cast<u32>(ds.skip_row_parity + 1) << flag::kSkipShift;
  r.flags = static_cast<s32>(f);
  r.page = ds.texpage_x | ds.texpage_y << 16;
  r.window = ds.win_and_u | ds.win_or_u << 8 | ds.win_and_v << 16 | ds.win_or_v << 24;
  return r;
}

int texture_mode(bool textured, const DrawState& ds) {
  return (textured && !ds.texture_disable) ? std::min(ds.tex_depth + 1, 3) : 0;
}

// Clips the native box [x0, x1) x [y0, y1) to the drawing area; false when nothing is left.
bool clip_box(PrimitiveRecord& r, s32 x0, s32 y0, s32 x1, s32 y1, const DrawState& ds) {
  r.bbox[0] = std::max(x0, ds.area_left), r.bbox[1] = std::max(y0, ds.area_top);
  r.bbox[2] = std::min(x1, ds.area_right + 1), r.bbox[3] = std::min(y1, ds.area_bottom + 1);
  return r.bbox[0] < r.bbox[2] && r.bbox[1] < r.bbox[3];
}

// The areas of VRAM a primitive reads: its texture page, and its own box when it blends or
// checks the mask bit (its palette comes from the CLUT cache). Returns how many were written to
// `reads` (at most 2).
u32 primitive_reads(const PrimitiveRecord& r, int tex, bool reads_back, u32 px, u32 py, Rect* reads) {
  u32 n = 0;
  static constexpr s32 kPageWidth[4] = {0, 64, 128, 256};
  if (tex) reads[n++] = {static_cast<s32>(px), static_cast<s32>(py), static_cast<s32>(px) + kPageWidth[tex],
                         static_cast<s32>(py) + 256};
  if (reads_back) reads[n++] = {r.bbox[0], r.bbox[1], r.bbox[2], r.bbox[3]};
  return n;
}

}  // namespace

void GlRenderer::draw_triangle(const Triangle& t, const DrawState& ds) {
  const SortedTriangle sorted = sort_by_y(t);
  const Vertex* const* p = sorted.p;
  const s64 cross = sorted.cross;
  const Vertex &a = *p[0], &b = *p[1], &c = *p[2];
  s32 min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
  if (max_x - min_x >= 1024 || c.y - a.y >= 512) return;
  if (cross == 0) return;

  const int tex = texture_mode(t.textured, ds);
  const bool raw = tex && t.raw;
  const bool gouraud = t.shaded && !raw;
  PrimitiveRecord r = state_record(Kind::Triangle, ds, tex, raw, t.semi, ds.dither && (gouraud || (tex && !raw)));
  if (!clip_box(r, min_x, a.y, max_x, c.y, ds)) return;
  if (cross > 0) r.flags |= static_cast<s32>(flag::kLongEdgeLeft);
  r.a[0] = a.x, r.a[1] = a.y, r.b[0] = b.x, r.b[1] = b.y, r.c[0] = c.x, r.c[1] = c.y;
  const Vertex& flat = t.v[0];  // flat polygons take the command's first colour
  const u8 colours[3][3] = {{a.r, b.r, c.r}, {a.g, b.g, c.g}, {a.b, b.b, c.b}};
  const u8 flat_colour[3] = {flat.r, flat.g, flat.b};
  // The planes start at the core vertex (as in the software renderer); the record holds their
  // value at the top vertex a, which the shader steps from.
  const Vertex& o = core_vertex(t);
  const u8 core_colour[3] = {o.r, o.g, o.b};
  for (int i = 0; i < 3; ++i) {
    if (gouraud) {
      Gradient g = plane_gradient(p, cross, colours[i][0], colours[i][1], colours[i][2]);
      r.base[i] = attribute_from_core(core_colour[i], g, o, a), r.grad[2 * i] = g.dx, r.grad[2 * i + 1] = g.dy;
    } else {
      r.base[i] = (s32{flat_colour[i]} << kFrac) + kHalf;
    }
  }
  if (tex) {
    Gradient gu = plane_gradient(p, cross, a.u, b.u, c.u), gv = plane_gradient(p, cross, a.v, b.v, c.v);
    r.base[3] = attribute_from_core(o.u, gu, o, a), r.grad[6] = gu.dx, r.grad[7] = gu.dy;
    r.base[4] = attribute_from_core(o.v, gv, o, a), r.grad[8] = gv.dx, r.grad[9] = gv.dy;
  }
  Rect reads[2];
  u32 n = primitive_reads(r, tex, t.semi || ds.check_mask, ds.texpage_x, ds.texpage_y, reads);
  if (tex == 1 || tex == 2) sync_palette();
  add(r, reads, n);
}

void GlRenderer::draw_rectangle(const Rectangle& rect, const DrawState& ds) {
  if (rect.width == 0 || rect.height == 0) return;
  const int tex = texture_mode(rect.textured, ds);
  PrimitiveRecord r = state_record(Kind::Rectangle, ds, tex, tex && rect.raw, rect.semi, false);
  if (!clip_box(r, rect.x, rect.y, rect.x + static_cast<s32>(rect.width), rect.y + static_cast<s32>(rect.height), ds))
    return;
  r.a[0] = rect.x, r.a[1] = rect.y;
  r.extra[0] = ds.flip_x ? -1 : 1, r.extra[1] = ds.flip_y ? -1 : 1;
  r.base[0] = rect.r, r.base[1] = rect.g, r.base[2] = rect.b, r.base[3] = rect.u, r.base[4] = rect.v;
  Rect reads[2];
  u32 n = primitive_reads(r, tex, rect.semi || ds.check_mask, ds.texpage_x, ds.texpage_y, reads);
  if (tex == 1 || tex == 2) sync_palette();
  add(r, reads, n);
}

void GlRenderer::draw_line(const Line& l, const DrawState& ds) {
  // Drawn from the left end point whatever the vertex order (the software renderer's rule).
  const bool swap = l.v[0].x > l.v[1].x;
  const Vertex &p0 = l.v[swap ? 1 : 0], &p1 = l.v[swap ? 0 : 1];
  const s32 dx = p1.x - p0.x, dy = p1.y - p0.y;
  if (std::abs(dx) >= 1024 || std::abs(dy) >= 512) return;
  const s32 steps = std::max(std::abs(dx), std::abs(dy));
  PrimitiveRecord r = state_record(Kind::Line, ds, 0, false, l.semi, ds.dither);  // flat ones too
  if (!clip_box(r, std::min(p0.x, p1.x), std::min(p0.y, p1.y), std::max(p0.x, p1.x) + 1, std::max(p0.y, p1.y) + 1, ds))
    return;
  r.a[0] = p0.x, r.a[1] = p0.y, r.b[0] = p1.x, r.b[1] = p1.y, r.c[0] = steps;
  const s32 c0[3] = {p0.r, p0.g, p0.b}, c1[3] = {p1.r, p1.g, p1.b};
  for (int i = 0; i < 3; ++i) {
    r.base[i] = (c0[i] << kFrac) + kHalf;
    if (l.shaded && steps) r.grad[2 * i] = ((c1[i] - c0[i]) << kFrac) / steps;
  }
  Rect reads[1];
  u32 n = primitive_reads(r, 0, l.semi || ds.check_mask, 0, 0, reads);
  add(r, reads, n);
}

}  // namespace psx::gpu::gl
