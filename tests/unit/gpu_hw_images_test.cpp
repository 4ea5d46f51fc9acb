// The software renderer against VRAM images captured from real consoles by JaCzekanski's
// ps1-tests (tests/data/ps1-tests/gpu/, MIT): each test sends the primitives that test program
// draws (read from its source and written out here as GP0 packets) and counts the VRAM pixels
// that differ from the capture: none may (before issue 59 the counts were 624 and 3227).
#include <png.h>

#include <string>
#include <vector>

#include "gpu/gl/gl_renderer.h"
#include "gpu/gl/osmesa_context.h"
#include "gpu_test_util.h"

namespace psx::test {
namespace {

// A console's VRAM image as 15-bit halfwords (bit 15 is not in the picture).
std::vector<u16> vram_image(const std::string& name) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  const std::string path = std::string(PSXRL_TESTDATA_DIR) + "/ps1-tests/gpu/" + name;
  EXPECT_TRUE(png_image_begin_read_from_file(&png, path.c_str())) << path;
  png.format = PNG_FORMAT_RGB;
  std::vector<u8> rgb(PNG_IMAGE_SIZE(png));
  EXPECT_TRUE(png_image_finish_read(&png, nullptr, rgb.data(), 0, nullptr)) << path;
  std::vector<u16> vram(1024 * 512);
  if (png.width != 1024 || png.height != 512) {
    ADD_FAILURE() << path << ": " << png.width << "x" << png.height;
    return vram;
  }
  for (size_t i = 0; i < vram.size(); ++i)
    vram[i] = static_cast<u16>(rgb[3 * i] >> 3 | (rgb[3 * i + 1] >> 3) << 5 | (rgb[3 * i + 2] >> 3) << 10);
  return vram;
}

class GpuHardwareImage : public GpuTest {
 protected:
  // ps1-tests common clearScreenColor(): four GP0(02) fills over all of VRAM.
  void clear(u32 rgb) {
    const u32 fill = 0x02000000 | rgb;
    gp0({fill, xy(0, 0), xy(512, 256), fill, xy(512, 0), xy(512, 256)});
    gp0({fill, xy(0, 256), xy(512, 256), fill, xy(512, 256), xy(0x3F1, 256)});
  }
  // setDrawTPage(dfe = 1, dither, texpage 0): GP0(E1).
  void e1(bool dither) { gp0({0xE1000400u | (dither ? 0x200u : 0u)}); }
  // Differing pixels in [x0, x1) x [y0, y1), skipping those `skip` names.
  template <typename Skip>
  int differing(const std::vector<u16>& want, u32 x0, u32 y0, u32 x1, u32 y1, Skip skip) {
    int n = 0;
    for (u32 y = y0; y < y1; ++y)
      for (u32 x = x0; x < x1; ++x) n += !skip(x, y) && (px(x, y) & 0x7FFF) != want[y * 1024 + x];
    return n;
  }
  void line(u32 rgb, s32 x0, s32 y0, s32 x1, s32 y1) { gp0({0x40000000 | rgb, xy(x0, y0), xy(x1, y1)}); }
  void gouraud_line(u32 rgb0, s32 x0, s32 y0, u32 rgb1, s32 x1, s32 y1) {
    gp0({0x50000000 | rgb0, xy(x0, y0), rgb1, xy(x1, y1)});
  }
};

// ps1-tests gpu/lines: every primitive but the circle (its end points come from PSn00bSDK's
// isin/icos tables) and the closing diagonal of the two Gouraud polylines (their fourth colour is
// never set by the program: uninitialised stack memory).
TEST_F(GpuHardwareImage, LinesMatchTheConsoleCapture) {
  clear(0xFFFFFF);
  e1(false);
  for (s32 i = 0; i < 10; ++i) line(0, 16, 16 + i * 8, 16 + 80, 16 + i * 8 + i);       // horizontal
  for (s32 i = 0; i < 10; ++i) line(0, 110 + i * 8, 16, 110 + i * 8 + i, 16 + 80);     // vertical
  for (s32 i = 0; i < 20; ++i) line(0, 200, 16 + i * 4, 200 + i, 16 + i * 4 + 1);      // short
  for (int dither = 0; dither < 2; ++dither) {
    e1(dither);
    const s32 x = dither ? 84 : 16;
    for (s32 i = 0; i < 64; ++i) line(0x0000AA, x, 100 + i, x + i, 100 + i);
    for (s32 i = 0; i < 64; ++i) gouraud_line(0, x, 166 + i, 0x0000FF, x + i, 166 + i);
  }
  for (int semi = 0; semi < 2; ++semi) {
    const u32 flags = semi ? 0x02000000u : 0u;
    const s32 x = semi ? 210 : 150;
    gp0({0x48000000 | flags | 0x0000AA, xy(x, 100), xy(x + 32, 100), xy(x + 32, 132), xy(x, 100), 0x55555555});
    gp0({0x58000000 | flags | 0x0000FF, xy(x, 140), 0x00FF00, xy(x + 32, 140), 0xFFFF00, xy(x + 32, 172),
         0x55555555});
  }
  std::vector<u16> want = vram_image("lines-vram.png");
  auto skip = [](u32 x, u32 y) {
    const bool circle = x >= 165 && x < 235 && y >= 165 && y < 235;
    const bool diagonal = y >= 140 && y <= 172 && ((x >= 150 && x <= 182 && x - 150 == y - 140) ||
                                                   (x >= 210 && x <= 242 && x - 210 == y - 140));
    return circle || diagonal;
  };
  const int n = differing(want, 0, 0, 1024, 512, skip);
  RecordProperty("differing_pixels", n);
  EXPECT_EQ(n, 0);
}

// ps1-tests gpu/triangle: three Gouraud triangles (red, green, blue corners), the last dithered.
TEST_F(GpuHardwareImage, GouraudTrianglesMatchTheConsoleCapture) {
  clear(0xFFFFFF);
  // drawTriangle(cx, cy, a): corners (cx -+ a/2, cy + h/2) and (cx, cy - h/2), h = a * 0.866025
  // in single precision, truncated to integers.
  auto triangle = [this](s32 cx, s32 cy, s32 a) {
    const float half_h = static_cast<float>(a) * 0.866025f / 2;
    const s32 bottom = static_cast<s32>(static_cast<float>(cy) + half_h);
    const s32 top = static_cast<s32>(static_cast<float>(cy) - half_h);
    gp0({0x300000FF, xy(cx - a / 2, bottom), 0x0000FF00, xy(cx + a / 2, bottom), 0x00FF0000, xy(cx, top)});
  };
  e1(false);
  triangle(160, 120, 240);
  triangle(768, 256, 500);
  e1(true);
  triangle(160, 360, 240);
  std::vector<u16> want = vram_image("triangle-vram.png");
  const int n = differing(want, 0, 0, 1024, 512, [](u32, u32) { return false; });
  RecordProperty("differing_pixels", n);
  EXPECT_EQ(n, 0);
}

// ps1-tests gpu/clut-cache: 8-bit textured 256x1 rectangles whose palette is rewritten in VRAM
// (by a fill, a line, or the rectangle itself drawn over it) with and without GP0(01), a change
// of CLUT position, and changes of texture depth between the draws. The capture shows which
// draws saw the palette cached before the rewrite.
class GpuClutCacheImage : public GpuHardwareImage {
 protected:
  // uploadToGPU(): a GP0(A0) row of `count` halfwords at (x, y), two per word.
  void upload(u32 x, u32 y, const std::vector<u16>& row) {
    gp0({0xA0000000, xy(static_cast<s32>(x), static_cast<s32>(y)), 0x00010000u | static_cast<u32>(row.size())});
    for (size_t n = 0; n < row.size(); n += 2) gp0({row[n] | u32{row[n + 1]} << 16});
  }
  // writeTestClut(): palette entry n = n.
  void test_clut(u32 x, u32 y) {
    std::vector<u16> row(256);
    for (u32 n = 0; n < 256; ++n) row[n] = static_cast<u16>(n);
    upload(x, y, row);
  }
  // 128 halfwords of 8-bit texel indices, index(i) | index(i + 1) << 8 for texels i and i + 1,
  // each a 16-bit value, not masked (as the program computes them).
  template <typename Index>
  void texture(u32 y, Index index) {
    std::vector<u16> row(128);
    for (u32 i = 0; i < 256; i += 2) row[i / 2] = static_cast<u16>(index(i) | index(i + 1) << 8);
    upload(0, y, row);
  }
  // rectangle(): GP0(64) 256x1 at (x, y), texcoord (0, v), colour 0x808080, CLUT at (cx, cy).
  void sprite(s32 x, s32 y, u32 v, u32 cx, u32 cy) {
    gp0({0x64808080, xy(x, y), (cy << 6 | cx >> 4) << 16 | v << 8, xy(256, 1)});
  }
  void white_fill(u32 y) { gp0({0x02FFFFFF, xy(0, static_cast<s32>(y)), xy(256, 1)}); }
  // setE1(mode, 0, 0): texture depth, drawing to the display area allowed.
  void depth(u32 mode) { gp0({0xE1000400u | mode << 7}); }
  void clear_cache() { gp0({0x01000000}); }
  // The program's draws; returns the VRAM pixels that differ from the capture.
  int run_program();
};

int GpuClutCacheImage::run_program() {
  clear(0);
  depth(1);
  s32 y = 20;
  const u32 cx = 0;
  auto row = [&y] { return static_cast<u32>(y); };
  test_clut(0, row()), clear_cache(), y += 16;  // testDummy
  texture(1, [](u32 i) { return i; });
  test_clut(0, row()), clear_cache(), sprite(0, y, 1, cx, row()), y += 16;
  texture(2, [](u32 i) { return 255 - i; });
  test_clut(0, row()), clear_cache(), sprite(0, y, 2, cx, row()), y += 16;
  texture(3, [](u32 i) { return u32{static_cast<u16>(i * (i << 3))}; });
  test_clut(0, row()), clear_cache(), sprite(0, y, 3, cx, row()), y += 16;
  // Reuse without and with GP0(01), then another CLUT position.
  test_clut(0, row()), sprite(0, y + 2, 1, cx, row()), white_fill(row()), sprite(0, y + 4, 1, cx, row()), y += 16;
  test_clut(0, row()), sprite(0, y + 2, 1, cx, row());
  line(0xFFFFFF, 0, y, 256, y), clear_cache(), sprite(0, y + 4, 1, cx, row()), y += 16;
  test_clut(0, row()), sprite(0, y + 2, 1, cx, row()), white_fill(row()), sprite(0, y + 4, 1, 16, row()), y += 16;
  // Texture depth changes between the two draws: 4->8, 8->4, 15->4, reserved->8, and 4->8->4
  // by GP0(E1) alone.
  const u32 changes[5][3] = {{0, 1, 1}, {1, 0, 0}, {2, 0, 0}, {3, 1, 1}, {0, 1, 0}};
  for (const auto& c : changes) {
    test_clut(0, row()), depth(c[0]), sprite(0, y + 2, 1, cx, row()), white_fill(row());
    depth(c[1]), depth(c[2]), sprite(0, y + 4, 1, cx, row()), y += 16;
  }
  // A 256-entry CLUT at x = 960 runs past the VRAM edge.
  y += 32;
  test_clut(960, row()), depth(1), sprite(0, y + 2, 1, 960, row());
  std::vector<u16> want = vram_image("clut-cache-vram.png");
  return differing(want, 0, 0, 1024, 512, [](u32, u32) { return false; });
}

TEST_F(GpuClutCacheImage, PalettesMatchTheConsoleCapture) {
  const int n = run_program();
  RecordProperty("differing_pixels", n);
  EXPECT_EQ(n, 0);
}

// The OpenGL renderer (OSMesa, headless) keeps the same cache (before, it read palettes from VRAM
// at draw time, as if it reloaded before every primitive: 768 pixels differed at both scales).
TEST_F(GpuClutCacheImage, OpenGlRendererMatchesTheConsoleCaptureAtScales1And4) {
  for (u32 scale : {1u, 4u}) {
    std::string error;
    auto gl = gpu::gl::make_osmesa_renderer(scale, gpu::gl::OsMesaContext::kDefaultLibrary, error);
    ASSERT_TRUE(gl) << "no OpenGL renderer: " << error;
    gpu.set_renderer(std::move(gl));
    gp1(0x00000000);
    gp0({0xE3000000, 0xE4000000 | (511u << 10) | 1023u});
    EXPECT_EQ(run_program(), 0) << "scale " << scale;
  }
}

}  // namespace
}  // namespace psx::test
