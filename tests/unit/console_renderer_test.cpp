// Console::use_gl_renderer, the renderer choice on the console's face (docs/architecture.md,
// Layers). Tumble sets a 320x240 display (GP1(08h), games/tumble/src/gpu.c): on the OpenGL
// renderer at scale 2 its frame is 640x480 while the native picture, which observations use, is
// the software renderer's; without OSMesa the call fails naming the library and the software
// renderer stays.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "tumble_console_util.h"

namespace {

using tumble_test::TumbleConsole;

TEST(ConsoleRenderer, GlAtScale2DrawsTumblesTitleAt640x480WithTheSoftwareNativePicture) {
  TumbleConsole sw, gl;
  std::string error;
  ASSERT_TRUE(gl.console.use_gl_renderer(2, error)) << error;
  sw.console.run_frames(30);
  gl.console.run_frames(30);
  psx::Console::Frame big = gl.console.frame(), native = gl.console.native_frame();
  psx::Console::Frame reference = sw.console.native_frame();
  EXPECT_EQ(big.width, 640u);
  EXPECT_EQ(big.height, 480u);
  ASSERT_EQ(native.width, 320u);
  ASSERT_EQ(native.height, 240u);
  ASSERT_EQ(reference.width, 320u);
  ASSERT_EQ(reference.height, 240u);
  EXPECT_EQ(std::memcmp(native.rgb, reference.rgb, 320 * 240 * 3), 0);
}

TEST(ConsoleRenderer, WithoutOsMesaTheCallFailsAndTheSoftwareRendererStays) {
  const char* missing = "/nonexistent/libOSMesa.so.8";
  ASSERT_EQ(setenv("PSXRL_OSMESA_LIBRARY", missing, 1), 0);
  TumbleConsole t;
  std::string error;
  EXPECT_FALSE(t.console.use_gl_renderer(2, error));
  unsetenv("PSXRL_OSMESA_LIBRARY");
  EXPECT_NE(error.find(missing), std::string::npos) << error;
  t.console.run_frames(30);
  EXPECT_EQ(t.console.frame().width, 320u);
  EXPECT_EQ(t.console.frame().height, 240u);
}

}  // namespace
