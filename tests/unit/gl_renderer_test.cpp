// The OpenGL renderer (OSMesa, headless) against the software renderer, the hardware-exact
// reference: at scale 1 both must leave VRAM identical after every kind of operation, in every
// mode (random primitives over random VRAM, compared after each small group); at scales 2 and 3
// the native view (each block's top-left sub-pixel) must equal it too. Left out: a textured
// primitive sampling texels it draws itself (samples_itself below).
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "gpu/gl/gl_renderer.h"
#include "gpu/gl/osmesa_context.h"
#include "gpu/software_renderer.h"
#include "gpu/vram.h"

namespace {

using namespace psx;
using namespace psx::gpu;

struct Rng {
  u32 state;
  u32 next() {
    state = state * 1664525u + 1013904223u;
    return state >> 8;
  }
  u32 below(u32 n) { return next() % n; }
  s32 range(s32 lo, s32 hi) { return lo + static_cast<s32>(below(static_cast<u32>(hi - lo + 1))); }
};

std::unique_ptr<Renderer> make_gl(u32 scale) {
  std::string error;
  auto r = gl::make_osmesa_renderer(scale, gl::OsMesaContext::kDefaultLibrary, error);
  if (!r) ADD_FAILURE() << "no OpenGL renderer: " << error;
  return r;
}

DrawState random_state(Rng& rng, bool allow_interlace) {
  DrawState ds;
  ds.texpage_x = static_cast<u16>(rng.below(16) * 64);
  ds.texpage_y = static_cast<u16>(rng.below(2) * 256);
  ds.semi_mode = static_cast<u8>(rng.below(4));
  ds.tex_depth = static_cast<u8>(rng.below(4));
  ds.dither = rng.below(2);
  ds.flip_x = rng.below(4) == 0;
  ds.flip_y = rng.below(4) == 0;
  ds.texture_disable = rng.below(8) == 0;
  if (rng.below(3) == 0) {
    u32 mu = rng.below(32), mv = rng.below(32), ou = rng.below(32), ov = rng.below(32);
    ds.win_and_u = static_cast<u8>(~(mu * 8)), ds.win_or_u = static_cast<u8>((ou & mu) * 8);
    ds.win_and_v = static_cast<u8>(~(mv * 8)), ds.win_or_v = static_cast<u8>((ov & mv) * 8);
  }
  ds.area_left = rng.range(0, 300), ds.area_top = rng.range(0, 200);
  ds.area_right = rng.range(ds.area_left, 1023), ds.area_bottom = rng.range(ds.area_top, 511);
  ds.set_mask = rng.below(4) == 0;
  ds.check_mask = rng.below(4) == 0;
  ds.skip_row_parity = allow_interlace && rng.below(4) == 0 ? static_cast<s32>(rng.below(2)) : -1;
  return ds;
}

Vertex random_vertex(Rng& rng, s32 cx, s32 cy, s32 spread) {
  Vertex v;
  v.x = cx + rng.range(-spread, spread), v.y = cy + rng.range(-spread, spread);
  v.r = static_cast<u8>(rng.below(256)), v.g = static_cast<u8>(rng.below(256)), v.b = static_cast<u8>(rng.below(256));
  v.u = static_cast<u8>(rng.below(256)), v.v = static_cast<u8>(rng.below(256));
  return v;
}

// Whether a textured primitive covering [x0, x1] x [y0, y1] could sample texels it draws itself:
// the software renderer then sees its own earlier rows, the OpenGL one the texture as it was
// before the primitive (and the hardware its texture cache): the documented difference.
bool samples_itself(const DrawState& ds, u16 clut_x, u16 clut_y, s32 x0, s32 y0, s32 x1, s32 y1) {
  auto overlaps = [&](s32 ax, s32 ay, s32 w, s32 h) {
    for (s32 dx : {0, 1024})  // the page may wrap past x = 1023
      if (ax - dx <= x1 && ax - dx + w > x0 && ay <= y1 && ay + h > y0) return true;
    return false;
  };
  return overlaps(ds.texpage_x, ds.texpage_y, 256, 256) || overlaps(clut_x, clut_y, 256, 1);
}

// The GPU loads the CLUT cache before a textured primitive that needs another palette
// (Gpu::clut_load()); here before each one, all 256 entries, on both renderers.
void load_palette(Renderer& a, Renderer& b, u32 clut_x, u32 clut_y) {
  a.load_clut(clut_x, clut_y, 256), b.load_clut(clut_x, clut_y, 256);
}

// One random operation of any kind, applied to both renderers.
void random_operation(Rng& rng, Renderer& a, Renderer& b) {
  const DrawState ds = random_state(rng, true);
  const s32 cx = rng.range(0, 1023), cy = rng.range(0, 511), spread = rng.below(4) == 0 ? 300 : 40;
  const u32 kind = rng.below(7);
  switch (kind) {
    case 0:
    case 1: {
      Triangle t;
      for (Vertex& v : t.v) v = random_vertex(rng, cx, cy, spread);
      t.clut_x = static_cast<u16>(rng.below(64) * 16), t.clut_y = static_cast<u16>(rng.below(512));
      t.shaded = rng.below(2), t.textured = rng.below(2), t.raw = rng.below(3) == 0, t.semi = rng.below(3) == 0;
      s32 x0 = std::min({t.v[0].x, t.v[1].x, t.v[2].x}), x1 = std::max({t.v[0].x, t.v[1].x, t.v[2].x});
      s32 y0 = std::min({t.v[0].y, t.v[1].y, t.v[2].y}), y1 = std::max({t.v[0].y, t.v[1].y, t.v[2].y});
      if (samples_itself(ds, t.clut_x, t.clut_y, x0, y0, x1, y1)) t.textured = false;
      if (t.textured) load_palette(a, b, t.clut_x, t.clut_y);
      a.draw_triangle(t, ds), b.draw_triangle(t, ds);
      break;
    }
    case 2: {
      Rectangle r;
      r.x = cx - 20, r.y = cy - 20, r.width = rng.below(80), r.height = rng.below(80);
      r.r = static_cast<u8>(rng.below(256)), r.g = static_cast<u8>(rng.below(256));
      r.b = static_cast<u8>(rng.below(256));
      r.u = static_cast<u8>(rng.below(256)), r.v = static_cast<u8>(rng.below(256));
      r.clut_x = static_cast<u16>(rng.below(64) * 16), r.clut_y = static_cast<u16>(rng.below(512));
      r.textured = rng.below(2), r.raw = rng.below(3) == 0, r.semi = rng.below(3) == 0;
      const s32 right = r.x + static_cast<s32>(r.width), bottom = r.y + static_cast<s32>(r.height);
      if (samples_itself(ds, r.clut_x, r.clut_y, r.x, r.y, right, bottom)) r.textured = false;
      if (r.textured) load_palette(a, b, r.clut_x, r.clut_y);
      a.draw_rectangle(r, ds), b.draw_rectangle(r, ds);
      break;
    }
    case 3: {
      Line l;
      for (Vertex& v : l.v) v = random_vertex(rng, cx, cy, spread);
      l.shaded = rng.below(2), l.semi = rng.below(3) == 0;
      a.draw_line(l, ds), b.draw_line(l, ds);
      break;
    }
    case 4: {
      u32 x = rng.below(64) * 16, y = rng.below(512), w = rng.below(20) * 16, h = rng.below(100);
      u16 pixel = static_cast<u16>(rng.next());
      a.fill(x, y, w, h, pixel), b.fill(x, y, w, h, pixel);
      break;
    }
    case 5: {
      u32 sx = rng.below(1024), sy = rng.below(512), dx = rng.below(1024), dy = rng.below(512);
      if (rng.below(2)) dx = (sx + rng.below(20)) & 1023, dy = (sy + rng.below(20)) & 511;  // overlapping
      u32 w = 1 + rng.below(100), h = 1 + rng.below(100);
      MaskMode m{ds.set_mask, ds.check_mask};
      a.copy(sx, sy, dx, dy, w, h, m), b.copy(sx, sy, dx, dy, w, h, m);
      break;
    }
    default: {
      std::vector<u16> row(1 + rng.below(200));
      for (u16& p : row) p = static_cast<u16>(rng.next());
      u32 x = rng.below(1024), y = rng.below(512);
      MaskMode m{ds.set_mask, ds.check_mask};
      a.write_row(x, y, row.data(), static_cast<u32>(row.size()), m);
      b.write_row(x, y, row.data(), static_cast<u32>(row.size()), m);
      break;
    }
  }
}

std::vector<u16> random_vram(Rng& rng) {
  std::vector<u16> v(kVramPixels);
  for (u16& p : v) p = static_cast<u16>(rng.next());
  // Some runs of transparent (0x0000) texels, as textures have.
  for (u32 i = 0; i < kVramPixels; i += 7) v[i] = 0;
  return v;
}

// Index of the first differing pixel, or -1.
long first_difference(const u16* a, const u16* b) {
  for (u32 i = 0; i < kVramPixels; ++i)
    if (a[i] != b[i]) return static_cast<long>(i);
  return -1;
}

// Random operations from random VRAM, compared every 25 operations.
void expect_random_operations_equal(u32 scale, u32 seed, int groups) {
  auto gl = make_gl(scale);
  ASSERT_TRUE(gl);
  SoftwareRenderer sw;
  Rng rng{seed};
  std::vector<u16> start = random_vram(rng);
  sw.load_vram(start.data());
  gl->load_vram(start.data());
  for (int group = 0; group < groups; ++group) {
    for (int i = 0; i < 25; ++i) random_operation(rng, sw, *gl);
    long diff = first_difference(sw.vram(), gl->vram());
    ASSERT_EQ(diff, -1) << "scale " << scale << ", group " << group << ": pixel (" << diff % 1024 << ", "
                        << diff / 1024 << ") software " << std::hex << sw.vram()[diff] << " OpenGL "
                        << gl->vram()[diff];
  }
}

TEST(GlRenderer, RandomOperationsAtScale1EqualTheSoftwareRenderer) { expect_random_operations_equal(1, 12345, 200); }

// At scale N the top-left sub-pixel of each block samples exactly the native point (coverage,
// attribute planes, texel and background reads all start there), so the native view is still
// the software renderer's.
TEST(GlRenderer, NativeViewAtScales2And3EqualsTheSoftwareRenderer) {
  expect_random_operations_equal(2, 2222, 40);
  expect_random_operations_equal(3, 3333, 20);
}

TEST(GlRenderer, LoadVramRoundTripsAtEveryScale) {
  Rng rng{777};
  std::vector<u16> start = random_vram(rng);
  for (u32 scale : {1u, 3u, 8u}) {
    auto gl = make_gl(scale);
    ASSERT_TRUE(gl);
    gl->load_vram(start.data());
    gl->fill(0, 0, 16, 1, 0x1234);  // forces a download instead of the cached copy
    std::vector<u16> expected = start;
    for (u32 x = 0; x < 16; ++x) expected[x] = 0x1234;
    EXPECT_EQ(first_difference(gl->vram(), expected.data()), -1) << "scale " << scale;
  }
}

}  // namespace
