// Rasterizer rules (psx-spx "GPU Rendering"): fill convention, size limits, clipping, offsets,
// Gouraud interpolation, dithering, lines and rectangles. Expected values are worked out in the
// comments from the documented rules.
#include <algorithm>

#include "gpu_test_util.h"

namespace psx::test {
namespace {

constexpr u32 kWhite = 0xF8F8F8;  // 8-bit 248 per channel -> 5-bit 31
constexpr u16 kWhite15 = 0x7FFF;

// psx-spx dither matrix, [y & 3][x & 3].
constexpr int kDither[4][4] = {{-4, 0, -3, 1}, {2, -2, 3, -1}, {-3, 1, -4, 0}, {3, -1, 2, -2}};

TEST_F(GpuTest, TriangleTopLeftFillRule) {
  // (0,0) (4,0) (0,4): the hypotenuse is x + y = 4. Row y covers 0 <= x < 4 - y (right edge
  // excluded) and rows 0..3 (bottom edge y = 4 excluded): 4 + 3 + 2 + 1 = 10 pixels.
  gp0({0x20000000 | kWhite, xy(0, 0), xy(4, 0), xy(0, 4)});
  int count = 0;
  for (u32 y = 0; y < 6; ++y)
    for (u32 x = 0; x < 6; ++x) {
      bool inside = static_cast<int>(x) < 4 - static_cast<int>(y);
      EXPECT_EQ(px(x, y), inside ? kWhite15 : 0) << x << "," << y;
      count += px(x, y) != 0;
    }
  EXPECT_EQ(count, 10);
}

TEST_F(GpuTest, QuadHalvesShareEdgeWithoutOverlap) {
  // Additive semi-transparency (E1 mode 1) of colour 8 (5-bit 1) over black: a pixel drawn by
  // both triangles of the quad would read 2. All 4x4 pixels must read exactly 1.
  gp0({0xE1000000 | (1 << 5)});
  gp0({0x2A080808, xy(10, 10), xy(14, 10), xy(10, 14), xy(14, 14)});
  for (u32 y = 9; y < 16; ++y)
    for (u32 x = 9; x < 16; ++x) {
      bool inside = x >= 10 && x < 14 && y >= 10 && y < 14;
      EXPECT_EQ(px(x, y), inside ? rgb15(1, 1, 1) : 0) << x << "," << y;
    }
}

TEST_F(GpuTest, TrianglesFollowTheEdgeRuleOnEveryRow) {
  // Random triangles, some clipped from the top (the first row drawn below the middle vertex).
  // Oracle from the fill rule alone: sort by y into a, b, c; row y (a.y <= y < c.y) is bounded
  // by the long edge a->c and by a->b above b.y, b->c from b.y on; pixel x is drawn when
  // left <= x < right for the exact edge positions, compared by cross-multiplying (no division).
  struct P {
    s64 x, y;
  };
  // x >= edge(p->q) on row y, for p.y < q.y: x*dy >= p.x*dy + (y - p.y)*(q.x - p.x).
  auto right_of = [](s64 x, s64 y, P p, P q) { return x * (q.y - p.y) >= p.x * (q.y - p.y) + (y - p.y) * (q.x - p.x); };
  u32 seed = 12345;
  auto next = [&](u32 range) {
    seed = seed * 1103515245u + 12345u;
    return static_cast<s64>((seed >> 8) % range);
  };
  for (int t = 0; t < 60; ++t) {
    P v[3];
    for (P& p : v) p = {next(300), next(300)};
    if (t % 4 == 1) v[1].y = std::min(v[0].y, v[2].y) + 1;  // the short edges switch on row 2
    const s64 top = t % 3 == 0 ? next(200) : 0;
    gp0({0xE3000000 | static_cast<u32>(top << 10), 0x02000000, 0, (320u << 16) | 320u});
    gp0({0x20000000 | kWhite, xy(s32(v[0].x), s32(v[0].y)), xy(s32(v[1].x), s32(v[1].y)), xy(s32(v[2].x), s32(v[2].y))});
    P s[3] = {v[0], v[1], v[2]};
    std::stable_sort(s, s + 3, [](P p, P q) { return p.y < q.y; });
    const s64 cross = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[2].x - s[0].x) * (s[1].y - s[0].y);
    for (s64 y = 0; y < 320; ++y)
      for (s64 x = 0; x < 320; ++x) {
        bool inside = false;
        if (cross != 0 && y >= std::max(s[0].y, top) && y < s[2].y) {
          const bool on_long = right_of(x, y, s[0], s[2]);
          const bool on_short = y < s[1].y ? right_of(x, y, s[0], s[1]) : right_of(x, y, s[1], s[2]);
          // The long edge is the left one when the middle vertex lies right of it (cross > 0).
          inside = cross > 0 ? on_long && !on_short : on_short && !on_long;
        }
        ASSERT_EQ(px(u32(x), u32(y)), inside ? kWhite15 : 0) << "triangle " << t << " at " << x << "," << y;
      }
  }
}

TEST_F(GpuTest, PolygonSizeLimits) {
  // Width 1024 (x from -512 to 512) is not drawn; 1023 is.
  gp0({0x20000000 | kWhite, xy(-512, 0), xy(512, 0), xy(-512, 2)});
  EXPECT_EQ(px(0, 0), 0);
  gp0({0x20000000 | kWhite, xy(-511, 0), xy(512, 0), xy(-511, 2)});
  EXPECT_EQ(px(0, 0), kWhite15);
  // Height 512 is not drawn; 511 is.
  gp0({0x20000000 | kWhite, xy(600, -256), xy(602, -256), xy(600, 256)});
  EXPECT_EQ(px(600, 100), 0);
  gp0({0x20000000 | kWhite, xy(600, -255), xy(602, -255), xy(600, 256)});
  EXPECT_EQ(px(600, 100), kWhite15);
}

TEST_F(GpuTest, DrawingAreaClipsInclusive) {
  gp0({0xE3000000 | (2 << 10) | 3, 0xE4000000 | (5 << 10) | 6});  // x 3..6, y 2..5
  gp0({0x28000000 | kWhite, xy(0, 0), xy(20, 0), xy(0, 20), xy(20, 20)});
  for (u32 y = 0; y < 10; ++y)
    for (u32 x = 0; x < 10; ++x)
      EXPECT_EQ(px(x, y), (x >= 3 && x <= 6 && y >= 2 && y <= 5) ? kWhite15 : 0) << x << "," << y;
}

TEST_F(GpuTest, DrawingOffsetIsSignedElevenBits) {
  // E5: x = 100, y = -1 (0x7FF in bits 11-21). A 1x1 rectangle at (5, 11) lands at (105, 10).
  gp0({0xE5000000 | (0x7FF << 11) | 100});
  gp0({0x68000000 | kWhite, xy(5, 11)});
  EXPECT_EQ(px(105, 10), kWhite15);
  // Vertex coordinates are bits 0-10, signed: x = 0x405 is -1019 (+100 is off screen), not 5
  // (which would land on (105, 11)); bit 11 is not part of the value, so 0x805 is 5.
  gp0({0x680000F8, xy(0x405, 12)});
  EXPECT_EQ(px(105, 11), 0);
  gp0({0x680000F8, xy(0x805, 13)});
  EXPECT_EQ(px(105, 12), 0x001F);
}

TEST_F(GpuTest, GouraudInterpolatesAcrossQuad) {
  // Red 0 on the left (x = 0), 248 on the right (x = 31): dR/dx = 248 / 31 = 8 per pixel, so the
  // pixel at x has red 8x (8-bit) = x (5-bit); green and blue are 0 everywhere.
  gp0({0x38000000, xy(0, 0), 0x0000F8, xy(31, 0), 0x000000, xy(0, 4), 0x0000F8, xy(31, 4)});
  for (u32 y = 0; y < 4; ++y)
    for (u32 x = 0; x < 31; ++x) EXPECT_EQ(px(x, y), rgb15(x, 0, 0)) << x << "," << y;
  EXPECT_EQ(px(31, 0), 0);
}

TEST_F(GpuTest, DitherAppliesToGouraudNotFlat) {
  gp0({0xE1000000 | (1 << 9)});
  // Gouraud with all corners 66: 5-bit = (66 + dither[y&3][x&3]) >> 3.
  gp0({0x38424242, xy(0, 0), 0x424242, xy(8, 0), 0x424242, xy(0, 8), 0x424242, xy(8, 8)});
  for (u32 y = 0; y < 8; ++y)
    for (u32 x = 0; x < 8; ++x) {
      u32 c = static_cast<u32>(66 + kDither[y & 3][x & 3]) >> 3;
      EXPECT_EQ(px(x, y), rgb15(c, c, c)) << x << "," << y;
    }
  // Flat untextured polygons and rectangles are not dithered: 66 >> 3 = 8.
  gp0({0x28424242, xy(20, 0), xy(28, 0), xy(20, 8), xy(28, 8)});
  gp0({0x60424242, xy(40, 0), 0x00080008});
  for (u32 y = 0; y < 8; ++y)
    for (u32 x = 0; x < 8; ++x) {
      EXPECT_EQ(px(20 + x, y), rgb15(8, 8, 8));
      EXPECT_EQ(px(40 + x, y), rgb15(8, 8, 8));
    }
}

TEST_F(GpuTest, DitherClampsAtChannelLimits) {
  // 2 + (-4) clamps at 0 and 255 + 3 clamps at 255: results 0 and 31 at dither -4 / +3 spots.
  gp0({0xE1000000 | (1 << 9)});
  gp0({0x3800FF02, xy(0, 0), 0x00FF02, xy(8, 0), 0x00FF02, xy(0, 8), 0x00FF02, xy(8, 8)});
  EXPECT_EQ(px(0, 0), rgb15(0, 31, 0));  // dither -4: red 2-4 -> 0, green 255-4 = 251 -> 31
  EXPECT_EQ(px(2, 1), rgb15(0, 31, 0));  // dither +3: red 5 -> 0, green 258 -> 255 -> 31
}

TEST_F(GpuTest, GouraudRowsStartingAtAnyColumn) {
  // Red 0 at x = 5, 248 at x = 36: dR/dx = 8, so pixel x has 5-bit red x - 5 (no dither). Rows
  // of 31 pixels from column 5: whole groups of eight pixels and a last group of seven.
  gp0({0x38000000, xy(5, 0), 0x0000F8, xy(36, 0), 0x000000, xy(5, 3), 0x0000F8, xy(36, 3)});
  for (u32 y = 0; y < 3; ++y) {
    EXPECT_EQ(px(4, y), 0) << y;
    for (u32 x = 5; x < 36; ++x) EXPECT_EQ(px(x, y), rgb15(x - 5, 0, 0)) << x << "," << y;
    EXPECT_EQ(px(36, y), 0) << y;
  }
}

TEST_F(GpuTest, GouraudRowsKeepMaskedPixelsAndDitherByColumn) {
  // Pixels with bit 15 (set by GP0(A0) data) in the path of a dithered Gouraud quad of constant
  // 66 from x = 3 to 21 (18 pixels: two groups of eight and two more), drawn with the mask
  // check on: those stay, every other pixel is (66 + dither[y & 3][x & 3]) >> 3 with bit 15
  // clear (GP0(E6) bit 0 off).
  gp0({0xE1000000 | (1 << 9)});
  poke(3, 0, 0x8001), poke(10, 1, 0x8002), poke(19, 2, 0x8003), poke(20, 3, 0x8004);
  gp0({0xE6000002});
  gp0({0x38424242, xy(3, 0), 0x424242, xy(21, 0), 0x424242, xy(3, 4), 0x424242, xy(21, 4)});
  EXPECT_EQ(px(3, 0), 0x8001);
  EXPECT_EQ(px(10, 1), 0x8002);
  EXPECT_EQ(px(19, 2), 0x8003);
  EXPECT_EQ(px(20, 3), 0x8004);
  for (u32 y = 0; y < 4; ++y)
    for (u32 x = 3; x < 21; ++x) {
      if ((x == 3 && y == 0) || (x == 10 && y == 1) || (x == 19 && y == 2) || (x == 20 && y == 3)) continue;
      u32 c = static_cast<u32>(66 + kDither[y & 3][x & 3]) >> 3;
      EXPECT_EQ(px(x, y), rgb15(c, c, c)) << x << "," << y;
    }
  EXPECT_EQ(px(21, 0), 0);
}

TEST_F(GpuTest, GouraudRowsEndAtTheLastVramColumn) {
  // Green 0 at x = 1000, 184 at x = 1023 (dG/dx = 8): pixel x has 5-bit green x - 1000, up to
  // column 1022 (the right edge is left out), with GP0(E6) bit 0 setting bit 15 on each. The
  // rows are VRAM's last two, so a group of eight pixels read past the row's end would fall
  // outside VRAM (the sanitizer build reports that).
  gp0({0xE6000001});
  gp0({0x38000000, xy(1000, 510), 0x00B800, xy(1023, 510), 0x000000, xy(1000, 512), 0x00B800, xy(1023, 512)});
  for (u32 y = 510; y < 512; ++y) {
    for (u32 x = 1000; x < 1023; ++x) EXPECT_EQ(px(x, y), 0x8000 | rgb15(0, x - 1000, 0)) << x << "," << y;
    EXPECT_EQ(px(1023, y), 0) << y;
  }
}

TEST_F(GpuTest, LinesIncludeBothEndpoints) {
  gp0({0x40000000 | kWhite, xy(0, 0), xy(5, 0)});
  for (u32 x = 0; x <= 5; ++x) EXPECT_EQ(px(x, 0), kWhite15);
  EXPECT_EQ(px(6, 0), 0);
  // Diagonal, drawn right to left: (13,3) (12,4) ... (10,6).
  gp0({0x40000000 | kWhite, xy(13, 3), xy(10, 6)});
  for (u32 i = 0; i <= 3; ++i) EXPECT_EQ(px(13 - i, 3 + i), kWhite15);
  EXPECT_EQ(px(12, 3), 0);
  // A single point.
  gp0({0x40000000 | kWhite, xy(30, 30), xy(30, 30)});
  EXPECT_EQ(px(30, 30), kWhite15);
}

TEST_F(GpuTest, LineSlopeSteps) {
  // (0,20) to (4,22): 4 steps in x, y advances 0.5 per step from 20.5 -> rows 20,21,21,22,22.
  gp0({0x40000000 | kWhite, xy(0, 20), xy(4, 22)});
  const u32 rows[5] = {20, 21, 21, 22, 22};
  for (u32 x = 0; x < 5; ++x) EXPECT_EQ(px(x, rows[x]), kWhite15) << x;
}

TEST_F(GpuTest, LineHalfStepsFollowTheLeftEndPointRule) {
  // Issue 59 item 4 (ps1-tests gpu/lines captures, Mednafen): a line is drawn from its left end
  // point whatever the vertex order; where the exact line passes midway between two pixels, x
  // rounds down and y rounds toward the right end point's y. Each case is drawn at its own origin
  // (ox, oy), which does not change it.
  struct Case {
    s32 x0, y0, x1, y1, x, y, not_x, not_y;
  };
  const Case cases[] = {
      {0, 0, 3, 10, 1, 5, 2, 5},    // x = 1.5 at y = 5: x rounds down
      {10, 0, 0, 3, 5, 1, 5, 2},    // y = 1.5 at x = 5: toward the right end point's y = 0
      {10, 10, 0, 7, 5, 9, 5, 8},   // y = 8.5 at x = 5: toward the right end point's y = 10
      {0, 0, 10, 3, 5, 2, 5, 1},    // y = 1.5 at x = 5: toward y = 3
  };
  for (int k = 0; k < 4; ++k) {
    const Case& c = cases[k];
    const s32 ox = 20 * k, oy = 100;
    gp0({0x40000000 | kWhite, xy(ox + c.x0, oy + c.y0), xy(ox + c.x1, oy + c.y1)});
    EXPECT_EQ(px(ox + c.x, oy + c.y), kWhite15) << "case " << k;
    EXPECT_EQ(px(ox + c.not_x, oy + c.not_y), 0) << "case " << k;
  }
}

TEST_F(GpuTest, GouraudLineInterpolates) {
  // Red 0 -> 240 over 30 steps: 8 per pixel, 5-bit red = x. Dither is off (E1.9 = 0).
  gp0({0x50000000, xy(0, 40), 0x0000F0, xy(30, 40)});
  for (u32 x = 0; x <= 30; ++x) EXPECT_EQ(px(x, 40), rgb15(x, 0, 0)) << x;
}

TEST_F(GpuTest, PolylineEndsAtTerminator) {
  // (0,50)-(4,50)-(4,54), then 55555555; the next word is a new command (1x1 rectangle).
  gp0({0x48000000 | kWhite, xy(0, 50), xy(4, 50), xy(4, 54), 0x55555555});
  gp0({0x6800F800, xy(20, 50)});
  for (u32 x = 0; x <= 4; ++x) EXPECT_EQ(px(x, 50), kWhite15);
  for (u32 y = 50; y <= 54; ++y) EXPECT_EQ(px(4, y), kWhite15);
  EXPECT_EQ(px(20, 50), rgb15(0, 31, 0));
  // Gouraud polyline: colour before each vertex; 5xxx5xxx in the colour slot terminates.
  gp0({0x580000F8, xy(0, 60), 0x0000F8, xy(3, 60), 0x00F800, xy(3, 63), 0x50005000});
  EXPECT_EQ(px(0, 60), rgb15(31, 0, 0));
  EXPECT_EQ(px(3, 63), rgb15(0, 31, 0));
  gp0({0x680000F8, xy(21, 50)});
  EXPECT_EQ(px(21, 50), rgb15(31, 0, 0));
}

TEST_F(GpuTest, RectangleSizes) {
  gp0({0x60000000 | kWhite, xy(0, 0), 0x00020003});  // variable 3x2
  gp0({0x68000000 | kWhite, xy(10, 0)});             // 1x1
  gp0({0x70000000 | kWhite, xy(20, 0)});             // 8x8
  gp0({0x78000000 | kWhite, xy(40, 0)});             // 16x16
  EXPECT_EQ(px(2, 1), kWhite15);
  EXPECT_EQ(px(3, 1), 0);
  EXPECT_EQ(px(2, 2), 0);
  EXPECT_EQ(px(10, 0), kWhite15);
  EXPECT_EQ(px(11, 0), 0);
  EXPECT_EQ(px(27, 7), kWhite15);
  EXPECT_EQ(px(28, 7), 0);
  EXPECT_EQ(px(55, 15), kWhite15);
  EXPECT_EQ(px(56, 15), 0);
  EXPECT_EQ(px(55, 16), 0);
}

TEST_F(GpuTest, MaskBitSetAndCheck) {
  gp0({0xE6000001});  // set mask on drawn pixels
  gp0({0x68000000 | kWhite, xy(0, 0)});
  EXPECT_EQ(px(0, 0), 0xFFFF);
  gp0({0xE6000002});  // check: keep pixels with bit 15
  gp0({0x680000F8, xy(0, 0)});
  gp0({0x680000F8, xy(1, 0)});
  EXPECT_EQ(px(0, 0), 0xFFFF);
  EXPECT_EQ(px(1, 0), rgb15(31, 0, 0));
}

}  // namespace
}  // namespace psx::test
