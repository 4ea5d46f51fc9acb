// Triangle set-up shared by the software and OpenGL renderers: the attribute planes (colours,
// texture coordinates) as 12-bit fixed-point gradients over the screen, computed the same way
// for both so that their interpolated values agree bit for bit.
#pragma once
#include "gpu/renderer.h"

namespace psx::gpu {

constexpr int kFrac = 12;  // fraction bits of the attribute interpolators

// d(attribute)/dx and d(attribute)/dy in 12-bit fixed point for the plane through three vertices.
struct Gradient {
  s32 dx = 0, dy = 0;
};

inline Gradient plane_gradient(const Vertex* p[3], s64 cross, s32 a0, s32 a1, s32 a2) {
  s64 ex1 = p[1]->x - p[0]->x, ey1 = p[1]->y - p[0]->y;
  s64 ex2 = p[2]->x - p[0]->x, ey2 = p[2]->y - p[0]->y;
  s64 d1 = a1 - a0, d2 = a2 - a0;
  Gradient g;
  g.dx = static_cast<s32>(((d1 * ey2 - d2 * ey1) * (s64{1} << kFrac)) / cross);
  g.dy = static_cast<s32>(((d2 * ex1 - d1 * ex2) * (s64{1} << kFrac)) / cross);
  return g;
}

}  // namespace psx::gpu
