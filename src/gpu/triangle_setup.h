// Triangle set-up shared by the software and OpenGL renderers: the vertices in row order with
// the edge cross product, and the attribute planes (colours, texture coordinates) as 12-bit
// fixed-point gradients over the screen, computed the same way for both so that their
// interpolated values agree bit for bit.
#pragma once
#include <utility>

#include "gpu/renderer.h"

namespace psx::gpu {

constexpr int kFrac = 12;  // fraction bits of the attribute interpolators

// A triangle's vertices sorted by y (stable, so equal rows keep command order), and the cross
// product of its edges a->b and a->c: 0 for a degenerate triangle (no area, nothing drawn),
// positive when the long edge a->c is on the left.
struct SortedTriangle {
  const Vertex* p[3];
  s64 cross;
};

inline SortedTriangle sort_by_y(const Triangle& t) {
  SortedTriangle s{{&t.v[0], &t.v[1], &t.v[2]}, 0};
  if (s.p[1]->y < s.p[0]->y) std::swap(s.p[0], s.p[1]);
  if (s.p[2]->y < s.p[1]->y) std::swap(s.p[1], s.p[2]);
  if (s.p[1]->y < s.p[0]->y) std::swap(s.p[0], s.p[1]);
  const Vertex &a = *s.p[0], &b = *s.p[1], &c = *s.p[2];
  s.cross = s64{b.x - a.x} * (c.y - a.y) - s64{c.x - a.x} * (b.y - a.y);
  return s;
}

// ceil(n / d) for d > 0.
inline s64 ceil_div(s64 n, s64 d) { return n >= 0 ? (n + d - 1) / d : -((-n) / d); }

// x of the edge a->b on row y, rounded up to the first pixel at or right of it.
inline s32 edge_x(const Vertex& a, const Vertex& b, s32 y) {
  s64 dy = b.y - a.y;
  return static_cast<s32>(ceil_div(s64{a.x} * dy + s64{y - a.y} * (b.x - a.x), dy));
}

// edge_x() on successive rows, without a division per row: the edge's x on row y is
// ceil(n / dy) with n = a.x*dy + (y - a.y)*(b.x - a.x), kept as quotient q and remainder
// r = q*dy - n (0 <= r < dy); the next row adds ceil(ex / dy) and carries the remainder.
class EdgeWalk {
 public:
  EdgeWalk() = default;
  // Starts on row y; the edge must not be horizontal (a.y < b.y).
  EdgeWalk(const Vertex& a, const Vertex& b, s32 y) : dy_(b.y - a.y) {
    const s64 ex = b.x - a.x;
    const s64 n = s64{a.x} * dy_ + s64{y - a.y} * ex;
    q_ = ceil_div(n, dy_);
    r_ = q_ * dy_ - n;
    step_q_ = ceil_div(ex, dy_);
    step_r_ = step_q_ * dy_ - ex;
  }
  s32 x() const { return static_cast<s32>(q_); }
  void next_row() {
    q_ += step_q_;
    r_ += step_r_;
    if (r_ >= dy_) {
      r_ -= dy_;
      --q_;
    }
  }

 private:
  s64 dy_ = 1, q_ = 0, r_ = 0, step_q_ = 0, step_r_ = 0;
};

// The pixels a non-degenerate sorted triangle covers on successive rows from y (a.y <= y < c.y),
// before clipping: left() <= x <= right(), the top-left fill rule leaving out the right edge.
// The edges are the long one a->c and the short one a->b above b, b->c from b on. The rasterizer
// and the deferred-drawing coverage test both walk this, so they agree on every pixel.
class SpanWalk {
 public:
  SpanWalk(const SortedTriangle& s, s32 y)
      : b_(*s.p[1]), c_(*s.p[2]), y_(y), long_left_(s.cross > 0), long_(*s.p[0], c_, y),
        short_(y < b_.y ? EdgeWalk(*s.p[0], b_, y) : EdgeWalk(b_, c_, y)) {}
  s32 left() const { return long_left_ ? long_.x() : short_.x(); }
  s32 right() const { return (long_left_ ? short_.x() : long_.x()) - 1; }
  void next_row() {
    ++y_;
    long_.next_row();
    if (y_ == b_.y && b_.y < c_.y) short_ = EdgeWalk(b_, c_, y_);  // not past a flat bottom
    else short_.next_row();
  }

 private:
  const Vertex &b_, &c_;
  s32 y_;
  bool long_left_;  // the middle vertex lies right of the long edge a->c
  EdgeWalk long_, short_;
};

// d(attribute)/dx and d(attribute)/dy in 12-bit fixed point for the plane through three vertices.
struct Gradient {
  s32 dx = 0, dy = 0;
};

inline Gradient plane_gradient(const Vertex* const p[3], s64 cross, s32 a0, s32 a1, s32 a2) {
  s64 ex1 = p[1]->x - p[0]->x, ey1 = p[1]->y - p[0]->y;
  s64 ex2 = p[2]->x - p[0]->x, ey2 = p[2]->y - p[0]->y;
  s64 d1 = a1 - a0, d2 = a2 - a0;
  Gradient g;
  g.dx = static_cast<s32>(((d1 * ey2 - d2 * ey1) * (s64{1} << kFrac)) / cross);
  g.dy = static_cast<s32>(((d2 * ex1 - d1 * ex2) * (s64{1} << kFrac)) / cross);
  return g;
}

// The vertex the interpolators start from: the leftmost one of the command's vertices, the later
// one of two at the same x when it is the second, the third on ties with it (Mednafen's "core
// vertex"; with truncated gradients the start decides the rounding, and this choice gives
// ps1-tests' gpu/triangle captures where the top vertex does not).
inline const Vertex& core_vertex(const Triangle& t) {
  if (t.v[1].x <= t.v[0].x) return t.v[2].x <= t.v[1].x ? t.v[2] : t.v[1];
  return t.v[2].x < t.v[0].x ? t.v[2] : t.v[0];
}

// An attribute's 12-bit fixed-point value at vertex `at`, interpolated from the core vertex `o`
// (value `base` there, plus half a unit) along the plane `g`.
inline s32 attribute_from_core(s32 base, const Gradient& g, const Vertex& o, const Vertex& at) {
  return static_cast<s32>((s64{base} << kFrac) + (1 << (kFrac - 1)) + s64{g.dx} * (at.x - o.x) +
                          s64{g.dy} * (at.y - o.y));
}

}  // namespace psx::gpu
