// The README's main command, run as written on the built files: `psxrl run` plays Tumble's level 1
// from the demo script, prints its summary and writes the screenshots. Expected values come from
// Tumble's source: the level's items, the HUD and the level-complete screen's drawing code.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string run(const std::string& command) {
  std::string out;
  FILE* p = ::popen((command + " 2>&1").c_str(), "r");
  if (!p) return out;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  EXPECT_EQ(::pclose(p), 0) << out;
  return out;
}

struct Rgb {
  unsigned width = 0, height = 0;
  std::vector<unsigned char> px;
  const unsigned char* at(unsigned x, unsigned y) const { return &px[(size_t{y} * width + x) * 3]; }
};

Rgb read_png(const fs::path& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  Rgb out;
  if (!png_image_begin_read_from_file(&image, path.c_str())) return out;
  image.format = PNG_FORMAT_RGB;
  out.px.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.px.data(), 0, nullptr)) return {};
  out.width = image.width;
  out.height = image.height;
  return out;
}

// The white texels of one glyph cell (the font's glyphs are white 7FFFh on a black shadow 8000h,
// hud.c hud_init; drawn with the neutral colour 808080h they stay white).
std::vector<bool> white_mask(const Rgb& img, unsigned x0, unsigned y0, unsigned size) {
  std::vector<bool> m;
  for (unsigned y = y0; y < y0 + size; ++y)
    for (unsigned x = x0; x < x0 + size; ++x) {
      const unsigned char* p = img.at(x, y);
      m.push_back(p[0] >= 230 && p[1] >= 230 && p[2] >= 230);
    }
  return m;
}

TEST(ReadmeCommand, PlaysTumbleLevel1AndSummarisesTheRun) {
  const fs::path dir = fs::path(::testing::TempDir()) / ("psxrl_readme_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string title = (dir / "tumble_title.png").string(), level = (dir / "tumble_level1.png").string(),
                    complete = (dir / "tumble_complete.png").string();
  // README.md's first command, after setup.sh has built into build/.
  const std::string out = run(std::string(PSXRL_BUILD_DIR) + "/psxrl run --exe " PSXRL_BUILD_DIR
                              "/games/tumble/tumble.exe --input " PSXRL_SOURCE_DIR
                              "/games/tumble/demo/level1.txt --frames 700 --screenshot-at 30 " +
                              title + " --screenshot-at 400 " + level + " --screenshot-at 699 " + complete);
  EXPECT_NE(out.find("psxrl run: 700 frames\n"), std::string::npos) << out;
  for (const std::string& f : {title, level, complete})
    EXPECT_NE(out.find("psxrl run: wrote " + f + "\n"), std::string::npos) << out;
  // Level 1 (games/tumble/levels/level01.txt) holds 8 coins, 2 fruit and 1 key, worth 250, 500
  // and 1000 (logic/level.h): 8 * 250 + 2 * 500 + 1000 = 4000, all collected by the demo, which
  // ends on the exit (state 20, success; game.toml's [episode] win = [20]).
  EXPECT_NE(out.find("psxrl run: tumble: level 1, score 4000, outcome win (state 20)\n"), std::string::npos) << out;

  const Rgb img = read_png(complete);
  // gpu.c sets GP1(08h) = 1: 320 dots, 240 lines (psx-spx "GPU Display Control Commands").
  ASSERT_EQ(img.width, 320u);
  ASSERT_EQ(img.height, 240u);
  // The HUD (hud.c hud_draw) writes "SCORE " + the score in 5 digits at (12, 10), 8 pixels a
  // character: "SCORE 04000" puts '0' at x = 60, 76, 84, 92 and '4' at x = 68. The same glyph
  // gives the same white pixels; '4' gives others.
  const auto zero = white_mask(img, 60, 10, 8), four = white_mask(img, 68, 10, 8);
  EXPECT_GT(std::count(zero.begin(), zero.end(), true), 0);
  for (unsigned x : {76u, 84u, 92u}) EXPECT_EQ(white_mask(img, x, 10, 8), zero) << "digit at x " << x;
  EXPECT_NE(four, zero);
  // The success screen (screens.c in_play) centres "LEVEL COMPLETE" at y 80, scale 2 (16-pixel
  // characters): x 48 to 271, y 80 to 95, in GOLD 2090C0h, which blends the white glyph to red
  // and green at their maximum (x1.5, x1.125) and blue at a quarter: yellow. Each of its 13
  // letters has at least one texel, four pixels at scale 2.
  int gold = 0;
  for (unsigned y = 80; y < 96; ++y)
    for (unsigned x = 48; x < 272; ++x) {
      const unsigned char* p = img.at(x, y);
      gold += p[0] >= 230 && p[1] >= 230 && p[2] <= 100;
    }
  EXPECT_GE(gold, 13 * 4);
  fs::remove_all(dir);
}

}  // namespace
