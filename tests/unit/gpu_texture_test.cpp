// Texture fetch (4/8-bit CLUT, 15-bit direct, texture window), modulation, semi-transparency
// equations and rectangle flipping (psx-spx "GPU Rendering", "Texture Attributes"). Expected
// values are computed in the comments from the documented formulas.
#include "gpu_test_util.h"

namespace psx::test {
namespace {

// Texture page 10 (x = 640, y = 0) and a CLUT at (32, 300): CLUT field = 32/16 | 300 << 6.
constexpr u32 kPage = 10;
constexpr u32 kClut = (32 / 16) | (300 << 6);
constexpr u32 uv(u32 u, u32 v, u32 attr = kClut) { return (attr << 16) | (v << 8) | u; }

class GpuTextureTest : public GpuTest {
 protected:
  void draw_mode(u32 depth, u32 semi = 0, u32 extra = 0) { gp0({0xE1000000 | kPage | (semi << 5) | (depth << 7) | extra}); }
};

TEST_F(GpuTextureTest, Clut4) {
  poke(640, 0, 0x3210);  // texels u=0..3 are CLUT indices 0, 1, 2, 3
  poke(32, 300, 0x0000);
  poke(33, 300, 0x001F);
  poke(34, 300, 0x03E0);
  poke(35, 300, 0xFC00);
  poke_rect(100, 100, 4, 1, 0x1111);
  draw_mode(0);
  gp0({0x65000000, xy(100, 100), uv(0, 0), 0x00010004});  // raw textured rectangle 4x1
  EXPECT_EQ(px(100, 100), 0x1111);  // index 0 -> 0x0000 is transparent: background stays
  EXPECT_EQ(px(101, 100), 0x001F);
  EXPECT_EQ(px(102, 100), 0x03E0);
  EXPECT_EQ(px(103, 100), 0xFC00);  // bit 15 of the texel is written
}

TEST_F(GpuTextureTest, Clut8) {
  poke(640, 1, 0x0201);  // u=0 -> index 1 (low byte), u=1 -> index 2
  poke(641, 1, 0x0003);  // u=2 -> index 3, u=3 -> index 0
  poke(33, 300, 0x001F);
  poke(34, 300, 0x03E0);
  poke(35, 300, 0x7C00);
  draw_mode(1);
  gp0({0x65000000, xy(100, 101), uv(0, 1), 0x00010004});
  EXPECT_EQ(px(100, 101), 0x001F);
  EXPECT_EQ(px(101, 101), 0x03E0);
  EXPECT_EQ(px(102, 101), 0x7C00);
  EXPECT_EQ(px(103, 101), 0x0000);  // CLUT entry 0 is 0 (VRAM starts cleared): transparent
}

TEST_F(GpuTextureTest, Direct15) {
  poke(640, 2, 0x1234);
  poke(641, 2, 0x8765);
  draw_mode(2);
  gp0({0x65000000, xy(100, 102), uv(0, 2), 0x00010002});
  EXPECT_EQ(px(100, 102), 0x1234);
  EXPECT_EQ(px(101, 102), 0x8765);
}

TEST_F(GpuTextureTest, TextureWindow) {
  for (u32 u = 0; u < 16; ++u) poke(640 + u, 3, static_cast<u16>(0x100 + u));
  draw_mode(2);
  // E2 mask X = 1 (8 texels), offset X = 1: u' = (u AND NOT 8) OR (1 AND 1) * 8 = u | 8.
  gp0({0xE2000000 | (1 << 10) | 1});
  gp0({0x65000000, xy(100, 103), uv(0, 3), 0x00010004});
  for (u32 i = 0; i < 4; ++i) EXPECT_EQ(px(100 + i, 103), 0x108 + i);
  // Offset bits outside the mask are ignored: offset 2 with mask 1 -> (2 AND 1) * 8 = 0, and
  // u = 8..11 lose bit 3 -> texels 0..3.
  gp0({0xE2000000 | (2 << 10) | 1});
  gp0({0x65000000, xy(100, 104), uv(8, 3), 0x00010004});
  for (u32 i = 0; i < 4; ++i) EXPECT_EQ(px(100 + i, 104), 0x100 + i);
}

TEST_F(GpuTextureTest, AffineQuadMapsTexelsOneToOne) {
  for (u32 v = 0; v < 8; ++v)
    for (u32 u = 0; u < 4; ++u) poke(640 + u, v, static_cast<u16>(0x200 + v * 16 + u));
  // Raw textured quad (page attribute in the second texcoord word): pixel (200+i, 200+j) reads
  // texel (i, 4+j) because du/dx = dv/dy = 1 exactly.
  const u32 page = kPage | (2 << 7);
  gp0({0x2D000000, xy(200, 200), uv(0, 4), xy(204, 200), uv(4, 4, page), xy(200, 204), uv(0, 8), xy(204, 204),
       uv(4, 8)});
  for (u32 j = 0; j < 4; ++j)
    for (u32 i = 0; i < 4; ++i) EXPECT_EQ(px(200 + i, 200 + j), 0x200 + (4 + j) * 16 + i) << i << "," << j;
  // The polygon's page attribute went into GPUSTAT bits 0-8.
  EXPECT_EQ(stat() & 0x1FF, page);
}

TEST_F(GpuTextureTest, ModulationIsColourTimesTexelOver128) {
  poke(640, 5, rgb15(31, 10, 0));
  draw_mode(2);
  // colour (64, 192, 128): r = 31*64/128 = 15, g = 10*192/128 = 15, b = 0.
  gp0({0x64000000 | (128 << 16) | (192 << 8) | 64, xy(101, 105), uv(0, 5), 0x00010001});
  EXPECT_EQ(px(101, 105), rgb15(15, 15, 0));
  // colour 255: r = 31*255/128 = 61 -> saturates at 31; g = 2550/128 = 19.
  gp0({0x64FFFFFF, xy(102, 105), uv(0, 5), 0x00010001});
  EXPECT_EQ(px(102, 105), rgb15(31, 19, 0));
  // colour 128 leaves the texel unchanged.
  gp0({0x64808080, xy(103, 105), uv(0, 5), 0x00010001});
  EXPECT_EQ(px(103, 105), rgb15(31, 10, 0));
}

TEST_F(GpuTextureTest, ModulatedGouraudTriangleIsDithered) {
  poke_rect(640, 6, 8, 8, rgb15(16, 16, 16));
  draw_mode(2, 0, 1 << 9);
  // Colour 0x80 everywhere: 8-bit value before dither = 16*128 >> 4 = 128; dithered 5-bit =
  // (128 + d) >> 3 = 15 where d < 0, 16 where d >= 0.
  gp0({0x3C808080, xy(300, 0), uv(0, 6), 0x808080, xy(308, 0), uv(8, 6, kPage | (2 << 7) | (1 << 9)), 0x808080,
       xy(300, 8), uv(0, 14), 0x808080, xy(308, 8), uv(8, 14)});
  constexpr int kDither[4][4] = {{-4, 0, -3, 1}, {2, -2, 3, -1}, {-3, 1, -4, 0}, {3, -1, 2, -2}};
  for (u32 y = 0; y < 8; ++y)
    for (u32 x = 0; x < 8; ++x) {
      u32 c = kDither[y & 3][x & 3] < 0 ? 15 : 16;
      EXPECT_EQ(px(300 + x, y), rgb15(c, c, c)) << x << "," << y;
    }
}

TEST_F(GpuTextureTest, RawPolygonRowsSkipTransparentTexelsAndKeepMaskedPixels) {
  // A raw 15-bit quad from x = 3 to 16 (13 pixels a row: a group of eight and five more) reading
  // texels u = 0..12 one to one: texel 0000h (u = 4) is transparent and a raw texel keeps its bit
  // 15 (u = 9). With the mask check on, a background pixel with bit 15 (x = 9) stays.
  for (u32 v = 20; v < 22; ++v)
    for (u32 u = 0; u < 13; ++u) poke(640 + u, v, u == 4 ? 0 : u == 9 ? 0x8123 : static_cast<u16>(0x100 + u));
  poke_rect(0, 50, 20, 2, 0x1111);
  poke(9, 50, 0x9999);
  gp0({0xE6000002});
  const u32 page = kPage | (2 << 7);
  gp0({0x2D000000, xy(3, 50), uv(0, 20), xy(16, 50), uv(13, 20, page), xy(3, 52), uv(0, 22), xy(16, 52), uv(13, 22)});
  for (u32 y = 50; y < 52; ++y) {
    EXPECT_EQ(px(2, y), 0x1111);
    for (u32 u = 0; u < 13; ++u) {
      const u32 x = 3 + u;
      const u16 want = (x == 9 && y == 50) ? 0x9999 : u == 4 ? 0x1111 : u == 9 ? 0x8123 : 0x100 + u;
      EXPECT_EQ(px(x, y), want) << x << "," << y;
    }
    EXPECT_EQ(px(16, y), 0x1111);
  }
}

TEST_F(GpuTextureTest, ModulatedClut8PolygonRows) {
  // An 8-bit CLUT quad of colour (64, 128, 255) from x = 5 to 22 (17 pixels a row, from a column
  // with x & 3 = 1), texel u = index u. CLUT entry k (k >= 1) is (k, 31 - k, b = min(31, 2k)),
  // with bit 15 for k = 5; entry 0 is 0000h, transparent. Modulation (psx-spx): 5-bit channel =
  // min(31, texel * colour / 128), so (k / 2, 31 - k, min(31, b * 255 / 128)), with the texel's
  // bit 15 and no dither (E1.9 off). The mask check (GP0(E6) = 2) keeps the background's masked
  // pixel at x = 14.
  const auto blue = [](u32 k) { return std::min(31u, 2 * k); };
  for (u32 k = 1; k < 17; ++k) poke(32 + k, 300, static_cast<u16>(rgb15(k, 31 - k, blue(k)) | (k == 5 ? 0x8000 : 0)));
  poke(32, 300, 0);
  for (u32 w = 0; w < 9; ++w) poke(640 + w, 30, static_cast<u16>((2 * w) | ((2 * w + 1) << 8)));
  poke_rect(0, 60, 30, 1, rgb15(1, 1, 1));
  poke(14, 60, 0x8000 | rgb15(2, 2, 2));
  gp0({0xE6000002});
  const u32 page = kPage | (1 << 7);
  gp0({0x2CFF8040, xy(5, 60), uv(0, 30), xy(22, 60), uv(17, 30, page), xy(5, 61), uv(0, 31), xy(22, 61), uv(17, 31)});
  EXPECT_EQ(px(4, 60), rgb15(1, 1, 1));
  for (u32 k = 0; k < 17; ++k) {
    const u32 x = 5 + k;
    u32 want = (k == 5 ? 0x8000 : 0) | rgb15(k / 2, 31 - k, std::min(31u, blue(k) * 255 / 128));
    if (k == 0) want = rgb15(1, 1, 1);          // transparent texel: background
    if (x == 14) want = 0x8000 | rgb15(2, 2, 2);  // masked background kept
    EXPECT_EQ(px(x, 60), want) << x;
  }
  EXPECT_EQ(px(22, 60), rgb15(1, 1, 1));
}

TEST_F(GpuTextureTest, SemiTransparencyEquations) {
  // Background (20, 10, 5); foreground colour (80, 160, 240) = 5-bit (10, 20, 30).
  const u16 back = rgb15(20, 10, 5);
  const u32 expected[4] = {
      rgb15(15, 15, 17),  // (B+F)/2: 30/2, 30/2, 35/2
      rgb15(30, 30, 31),  // B+F saturated: 30, 30, 35 -> 31
      rgb15(10, 0, 0),    // B-F clamped at 0: 10, -10 -> 0, -25 -> 0
      rgb15(22, 15, 12),  // B+F/4: 20+2, 10+5, 5+7
  };
  for (u32 mode = 0; mode < 4; ++mode) {
    poke(400 + mode, 0, back);
    gp0({0xE1000000 | (mode << 5)});
    gp0({0x6AF0A050, xy(400 + mode, 0)});  // 1x1 semi-transparent rectangle
    EXPECT_EQ(px(400 + mode, 0), expected[mode]) << "mode " << mode;
  }
}

TEST_F(GpuTextureTest, TexturedBlendingOnlyWhereBit15) {
  poke(640, 7, rgb15(2, 2, 2));
  poke(641, 7, 0x8000 | rgb15(2, 2, 2));
  poke_rect(100, 107, 2, 1, rgb15(1, 1, 1));
  draw_mode(2, 1);  // B+F
  gp0({0x67000000, xy(100, 107), uv(0, 7), 0x00010002});  // raw, semi-transparent
  EXPECT_EQ(px(100, 107), rgb15(2, 2, 2));           // bit 15 clear: opaque
  EXPECT_EQ(px(101, 107), 0x8000 | rgb15(3, 3, 3));  // bit 15 set: 1+2, bit 15 kept
}

TEST_F(GpuTextureTest, RectangleFlip) {
  for (u32 u = 0; u < 4; ++u) poke(640 + u, 8, static_cast<u16>(0x300 + u));
  draw_mode(2, 0, 1 << 12);  // E1.12: X flip
  gp0({0x65000000, xy(100, 108), uv(3, 8), 0x00010004});
  for (u32 i = 0; i < 4; ++i) EXPECT_EQ(px(100 + i, 108), 0x303 - i);
  // Y flip: row v = 9 then v = 8 going down.
  poke(640, 9, 0x0399);
  draw_mode(2, 0, 1 << 13);
  gp0({0x65000000, xy(110, 108), uv(0, 9), 0x00020001});
  EXPECT_EQ(px(110, 108), 0x0399);
  EXPECT_EQ(px(110, 109), 0x0300);
}

}  // namespace
}  // namespace psx::test
