// The VRAM rectangles of a kept renderer call (see draw_command.h). The bounds follow the software
// rasterizer's rules (software_renderer_*.cpp): primitives stay inside the drawing area and are
// dropped when they span 1024 or more columns or 512 or more rows; block operations wrap.
#include "gpu/draw_command.h"

#include <algorithm>
#include <cstdlib>

#include "gpu/triangle_setup.h"

namespace psx::gpu {
namespace {

Rect area_rect(const DrawState& ds) { return {ds.area_left, ds.area_top, ds.area_right + 1, ds.area_bottom + 1}; }

Rect clip(const Rect& r, const Rect& to) {
  return {std::max(r.x0, to.x0), std::max(r.y0, to.y0), std::min(r.x1, to.x1), std::min(r.y1, to.y1)};
}

// The bounding box of a and b (an empty one adds nothing).
Rect bounding(const Rect& a, const Rect& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

// What a triangle may write: its bounding box in the drawing area, or nothing when it spans too
// many columns or rows to be drawn.
Rect triangle_write(const Vertex& a, const Vertex& b, const Vertex& c, const DrawState& ds) {
  const s32 min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
  const s32 min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
  if (max_x - min_x >= 1024 || max_y - min_y >= 512) return {};
  return clip({min_x, min_y, max_x + 1, max_y + 1}, area_rect(ds));
}

bool same_area(const DrawState& a, const DrawState& b) {
  return a.area_left == b.area_left && a.area_top == b.area_top && a.area_right == b.area_right &&
         a.area_bottom == b.area_bottom;
}

// A texture page's texels (64, 128 or 256 halfwords wide by 256 rows for 4-bit, 8-bit and 15-bit
// texels; depth 3 acts as 15-bit) and its CLUT row (16 or 256 entries).
u32 texture_reads(const DrawState& ds, u32 clut_x, u32 clut_y, Rect out[3]) {
  static constexpr u32 kPageWidth[4] = {64, 128, 256, 256};
  out[0] = wrapped_block(ds.texpage_x, ds.texpage_y, kPageWidth[ds.tex_depth & 3], 256);
  if (ds.tex_depth >= 2) return 1;
  out[1] = wrapped_block(clut_x, clut_y, ds.tex_depth == 0 ? 16 : 256, 1);
  return 2;
}

// A textured or a semi-transparent triangle, or one under the mask check, reads VRAM.
u32 triangle_reads(const Triangle& t, const DrawState& ds, const Rect& write, Rect out[3]) {
  u32 n = 0;
  if (t.textured) n = texture_reads(ds, t.clut_x, t.clut_y, out);
  if (t.semi || ds.check_mask) out[n++] = write;
  return n;
}

// Opaque, untextured, no mask check, every row drawn: each covered pixel is replaced outright.
bool replaces_covered(const Triangle& t, const DrawState& ds) {
  return !t.textured && !t.semi && !ds.check_mask && ds.skip_row_parity < 0;
}

// The rows a triangle covers, as the rasterizer draws it: false when it draws nothing.
bool triangle_rows(const Triangle& t, const DrawState& ds, SortedTriangle& s, s32& y_begin, s32& y_end) {
  s32 min_x = std::min({t.v[0].x, t.v[1].x, t.v[2].x}), max_x = std::max({t.v[0].x, t.v[1].x, t.v[2].x});
  s32 min_y = std::min({t.v[0].y, t.v[1].y, t.v[2].y}), max_y = std::max({t.v[0].y, t.v[1].y, t.v[2].y});
  if (max_x - min_x >= 1024 || max_y - min_y >= 512) return false;
  s = sort_by_y(t);
  if (s.cross == 0) return false;
  y_begin = std::max(s.p[0]->y, ds.area_top);
  y_end = std::min(s.p[2]->y - 1, ds.area_bottom);
  return y_begin <= y_end;
}

}  // namespace

Rect wrapped_block(u32 x, u32 y, u32 width, u32 height) {
  if (width == 0 || height == 0) return {};
  x &= kVramWidth - 1, y &= kVramHeight - 1;
  Rect r{static_cast<s32>(x), static_cast<s32>(y), static_cast<s32>(x + width), static_cast<s32>(y + height)};
  if (r.x1 > static_cast<s32>(kVramWidth)) r.x0 = 0, r.x1 = kVramWidth;
  if (r.y1 > static_cast<s32>(kVramHeight)) r.y0 = 0, r.y1 = kVramHeight;
  return r;
}

Rect DrawCommand::write_rect() const {
  switch (kind) {
    case Kind::Triangle: return triangle_write(triangle.v[0], triangle.v[1], triangle.v[2], ds);
    case Kind::Quad: {
      const Vertex *v = quad.first.v, &last = quad.last;
      const s32 min_x = std::min({v[0].x, v[1].x, v[2].x, last.x}), max_x = std::max({v[0].x, v[1].x, v[2].x, last.x});
      const s32 min_y = std::min({v[0].y, v[1].y, v[2].y, last.y}), max_y = std::max({v[0].y, v[1].y, v[2].y, last.y});
      if (max_x - min_x < 1024 && max_y - min_y < 512) return clip({min_x, min_y, max_x + 1, max_y + 1}, area_rect(ds));
      // Too large as a whole: each half is dropped or drawn on its own.
      return bounding(triangle_write(v[0], v[1], v[2], ds), triangle_write(v[1], v[2], last, ds));
    }
    case Kind::Line: {
      const Vertex &a = line.v[0], &b = line.v[1];
      if (std::abs(b.x - a.x) >= 1024 || std::abs(b.y - a.y) >= 512) return {};
      return clip({std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x) + 1, std::max(a.y, b.y) + 1},
                  area_rect(ds));
    }
    case Kind::Rectangle: {
      const Rectangle& r = rectangle;
      return clip({r.x, r.y, r.x + static_cast<s32>(r.width), r.y + static_cast<s32>(r.height)}, area_rect(ds));
    }
    case Kind::Fill:
    case Kind::Copy: return wrapped_block(block.x, block.y, block.width, block.height);
    case Kind::Row: return wrapped_block(block.x, block.y, block.width, 1);
    case Kind::ClutLoad: return {};
  }
  return {};
}

u32 DrawCommand::read_rects(Rect out[3]) const {
  u32 n = 0;
  switch (kind) {
    case Kind::Triangle: return triangle_reads(triangle, ds, write, out);
    case Kind::Quad: return triangle_reads(quad.first, ds, write, out);
    case Kind::Line:
      if (line.semi || ds.check_mask) out[n++] = write;
      return n;
    case Kind::Rectangle:
      if (rectangle.textured) n = texture_reads(ds, rectangle.clut_x, rectangle.clut_y, out);
      if (rectangle.semi || ds.check_mask) out[n++] = write;
      return n;
    case Kind::Fill: return 0;
    case Kind::Copy:
      out[n++] = wrapped_block(block.sx, block.sy, block.width, block.height);
      if (block.mask.check) out[n++] = write;
      return n;
    case Kind::Row:
      if (block.mask.check) out[n++] = write;
      return n;
    case Kind::ClutLoad:
      out[n++] = wrapped_block(block.x, block.y, block.width, 1);
      return n;
  }
  return n;
}

bool DrawCommand::textured() const {
  switch (kind) {
    case Kind::Triangle: return triangle.textured;
    case Kind::Quad: return quad.first.textured;
    case Kind::Rectangle: return rectangle.textured;
    default: return false;
  }
}

u32 DrawCommand::clut_x() const {
  return kind == Kind::Rectangle ? rectangle.clut_x : kind == Kind::Quad ? quad.first.clut_x : triangle.clut_x;
}

u32 DrawCommand::clut_y() const {
  return kind == Kind::Rectangle ? rectangle.clut_y : kind == Kind::Quad ? quad.first.clut_y : triangle.clut_y;
}

Rect DrawCommand::overwrite_rect() const {
  if (kind == Kind::Fill) {
    const Rect r = wrapped_block(block.x, block.y, block.width, block.height);
    // A fill that wraps covers two pieces, not the superset wrapped_block gives.
    const bool whole = r.x1 - r.x0 == static_cast<s32>(block.width) && r.y1 - r.y0 == static_cast<s32>(block.height);
    return whole ? r : Rect{};
  }
  if (kind == Kind::Rectangle && !rectangle.textured && !rectangle.semi && !ds.check_mask && ds.skip_row_parity < 0)
    return write_rect();
  return {};
}

bool may_pair_cover(DrawnTriangle first, DrawnTriangle second) {
  if (!replaces_covered(first.t, first.ds) || !replaces_covered(second.t, second.ds)) return false;
  if (!same_area(first.ds, second.ds)) return false;
  const DrawState& ds = first.ds;
  const Vertex* v[6] = {&first.t.v[0], &first.t.v[1], &first.t.v[2], &second.t.v[0], &second.t.v[1], &second.t.v[2]};
  s32 x0 = v[0]->x, x1 = v[0]->x, y0 = v[0]->y, y1 = v[0]->y;
  for (const Vertex* p : v) {
    x0 = std::min(x0, p->x), x1 = std::max(x1, p->x);
    y0 = std::min(y0, p->y), y1 = std::max(y1, p->y);
  }
  for (const Vertex* p : v) {
    const bool x_inside = p->x > ds.area_left && p->x <= ds.area_right;
    const bool y_inside = p->y > ds.area_top && p->y <= ds.area_bottom;
    if ((x_inside && p->x != x0 && p->x != x1) || (y_inside && p->y != y0 && p->y != y1)) return false;
  }
  return true;
}

Rect triangle_pair_cover(DrawnTriangle first, DrawnTriangle second) {
  if (!replaces_covered(first.t, first.ds) || !replaces_covered(second.t, second.ds)) return {};
  if (!same_area(first.ds, second.ds)) return {};
  SortedTriangle s[2];
  s32 begin[2], end[2];
  if (!triangle_rows(first.t, first.ds, s[0], begin[0], end[0])) return {};
  if (!triangle_rows(second.t, second.ds, s[1], begin[1], end[1])) return {};
  const DrawState& ds = first.ds;
  // Every row from the first covered to the last must be covered from the same left to the same
  // right pixel by the union of the two spans (clipped to the drawing area, as drawn).
  Rect cover{0, std::min(begin[0], begin[1]), 0, std::max(end[0], end[1]) + 1};
  SpanWalk walk[2] = {SpanWalk(s[0], begin[0]), SpanWalk(s[1], begin[1])};
  for (s32 y = cover.y0; y < cover.y1; ++y) {
    s32 left[2], right[2];
    u32 spans = 0;
    for (u32 i = 0; i < 2; ++i) {
      if (y < begin[i] || y > end[i]) continue;
      left[spans] = std::max(walk[i].left(), ds.area_left), right[spans] = std::min(walk[i].right(), ds.area_right);
      walk[i].next_row();
      if (left[spans] <= right[spans]) ++spans;
    }
    if (spans == 0) return {};
    s32 l = left[0], r = right[0];
    if (spans == 2) {
      if (left[1] > r + 1 || l > right[1] + 1) return {};  // a gap between the two spans
      l = std::min(l, left[1]), r = std::max(r, right[1]);
    }
    if (y == cover.y0) {
      cover.x0 = l, cover.x1 = r + 1;
    } else if (l != cover.x0 || r + 1 != cover.x1) {
      return {};
    }
  }
  return cover;
}

}  // namespace psx::gpu
