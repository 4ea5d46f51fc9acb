// Tumble through the OpenGL renderer (OSMesa, headless). At scale 1 the pictures, VRAM and even
// whole save states equal the software renderer's along the README's demo (title, level 1 in
// play, the level's end): the renderer is invisible to the game and to states. At scale 4 the
// level-1 picture is 1280x960 and matches tests/data/gl/tumble_level1_scale4.png, a regression
// image checked by eye once (regenerate it with the command in docs/renderer.md).
#include <gtest/gtest.h>
#include <png.h>

#include <cstring>
#include <string>
#include <vector>

#include "cli/input_script.h"
#include "gpu/gl/gl_renderer.h"
#include "gpu/gl/osmesa_context.h"
#include "tumble_console_util.h"

namespace {

using tumble_test::TumbleConsole;

void use_gl(psx::Console& console, psx::u32 scale) {
  std::string error;
  auto r = psx::gpu::gl::make_osmesa_renderer(scale, psx::gpu::gl::OsMesaContext::kDefaultLibrary, error);
  ASSERT_TRUE(r) << error;
  console.set_renderer(std::move(r));
}

// The demo's presses for frame f (as psxrl run --input applies them).
struct Demo {
  std::vector<psxrl::cli::InputPress> presses =
      psxrl::cli::read_input_script(std::string(TUMBLE_DEMO_DIR) + "/level1.txt");
  size_t next = 0;
  void frame(psx::Console& c, psx::u64 f) {
    for (; next < presses.size() && presses[next].frame == f; ++next)
      c.press_for(1, presses[next].buttons, presses[next].hold);
    c.run_frame();
  }
};

bool same_frame(const psx::Console& a, const psx::Console& b) {
  psx::Console::Frame fa = a.frame(), fb = b.frame();
  return fa.width == fb.width && fa.height == fb.height &&
         std::memcmp(fa.rgb, fb.rgb, size_t{fa.width} * fa.height * 3) == 0;
}

TEST(GlTumble, Scale1PicturesVramAndStatesEqualTheSoftwareRenderersAlongTheDemo) {
  TumbleConsole sw, gl;
  use_gl(gl.console, 1);
  Demo dsw, dgl;
  // 30: the title; 400: level 1 in play (the README's screenshots); 699: the level's end.
  const psx::u64 checks[] = {30, 150, 400, 550, 699};
  psx::u64 f = 0;
  for (psx::u64 check : checks) {
    for (; f <= check; ++f) dsw.frame(sw.console, f), dgl.frame(gl.console, f);
    EXPECT_TRUE(same_frame(sw.console, gl.console)) << "frame " << check;
    EXPECT_EQ(std::memcmp(sw.console.vram(), gl.console.vram(), 1024 * 512 * 2), 0) << "frame " << check;
    EXPECT_EQ(sw.console.save_state(), gl.console.save_state()) << "frame " << check;
  }
}

TEST(GlTumble, StateSavedUnderGlLoadsIntoTheSoftwareRendererAndBack) {
  TumbleConsole sw, gl;
  use_gl(gl.console, 4);
  ASSERT_TRUE(gl.start_level(1));
  ASSERT_TRUE(gl.run_game_frames(10));
  std::vector<psx::u8> state = gl.console.save_state();
  sw.console.load_state(state);
  EXPECT_EQ(sw.console.save_state(), state);
  // And back: the GL console takes the software console's VRAM, at its scale.
  sw.run_game_frames(5);
  gl.console.load_state(sw.console.save_state());
  EXPECT_EQ(std::memcmp(sw.console.vram(), gl.console.vram(), 1024 * 512 * 2), 0);
  EXPECT_EQ(gl.console.frame().width, 320u * 4);
}

TEST(GlTumble, Scale4Level1PictureIs1280x960AndMatchesTheRegressionImage) {
  TumbleConsole gl;
  use_gl(gl.console, 4);
  Demo demo;
  for (psx::u64 f = 0; f <= 400; ++f) demo.frame(gl.console, f);
  psx::Console::Frame frame = gl.console.frame();
  ASSERT_EQ(frame.width, 1280u);
  ASSERT_EQ(frame.height, 960u);
  const std::string path = std::string(PSXRL_TESTDATA_DIR) + "/gl/tumble_level1_scale4.png";
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&png, path.c_str())) << path;
  png.format = PNG_FORMAT_RGB;
  std::vector<psx::u8> expected(PNG_IMAGE_SIZE(png));
  ASSERT_TRUE(png_image_finish_read(&png, nullptr, expected.data(), 0, nullptr)) << path;
  ASSERT_EQ(png.width, 1280u);
  ASSERT_EQ(png.height, 960u);
  size_t differing = 0;
  for (size_t i = 0; i < expected.size(); ++i) differing += expected[i] != frame.rgb[i];
  EXPECT_EQ(differing, 0u) << "bytes differing from " << path;
  // The native picture beside it is the software renderer's top-left samples: still the game.
  psx::Console::Frame native = gl.console.native_frame();
  EXPECT_EQ(native.width, 320u);
  EXPECT_EQ(std::memcmp(native.rgb, frame.rgb, 3), 0);
}

}  // namespace
