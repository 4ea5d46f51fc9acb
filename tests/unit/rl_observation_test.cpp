// Observation encoders and level maps (src/rl/observation.h, level_map.h) on hand-worked cases:
// the seed's simple index, the agent-local crop rotated to each facing, frame crops and planes,
// and the MFCC shape from python_speech_features' framing rule.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/input_error.h"
#include "rl/env.h"
#include "rl/level_map.h"
#include "rl/observation.h"

using namespace psxrl::rl;

namespace {

// Tumble's level 1 (games/tumble/levels/level01.txt): 5 wide, 6 high, S at (2, 5).
const char* kLevel1 =
    "name: FIRST STEPS\ntime: 60\nfacing: N\nmap:\n"
    "E###k\n"
    "#c#c#\n"
    "#f#f#\n"
    "#c#c#\n"
    "#c#c#\n"
    "#cSc#\n";

}  // namespace

TEST(LevelMap, ParsesHeaderAndTiles) {
  LevelMap m = parse_level_map(kLevel1, "level01.txt");
  EXPECT_EQ(m.name, "FIRST STEPS");
  EXPECT_EQ(m.time_seconds, 60);
  EXPECT_EQ(m.facing, 0);
  EXPECT_EQ(m.width, 5);
  EXPECT_EQ(m.height, 6);
  EXPECT_EQ(m.start_x, 2);
  EXPECT_EQ(m.start_y, 5);
  EXPECT_EQ(m.at(0, 0), Tile::Exit);
  EXPECT_EQ(m.at(4, 0), Tile::Key);
  EXPECT_EQ(m.at(-1, 0), Tile::Void);
  EXPECT_EQ(m.at(5, 5), Tile::Void);
}

TEST(LevelMap, DefectsNameTheLine) {
  auto error = [](const std::string& text) {
    try {
      parse_level_map(text, "m.txt");
    } catch (const psx::InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("name: X\ntime: 60\nfacing: Q\nmap:\nS#E\n"), "m.txt:3: facing: expected N, E, S or W");
  EXPECT_EQ(error("name: X\ntime: 60\nfacing: N\nmap:\nS#E\n#x#\n"), "m.txt:6: expected a map character (. # S E ^ % c f k), found 'x'");
  EXPECT_EQ(error("name: X\ntime: 60\nfacing: N\nmap:\nS##\n"), "m.txt:5: expected exactly one 'S' and one 'E' in the map, found 1 and 0");
  EXPECT_EQ(error("name: X\nmap:\nSE\n"), "m.txt:2: missing name:, time: or facing: before map:");
  EXPECT_EQ(error("name: X\ntime: 60\n"), "m.txt:2: expected 'map:' followed by the map rows");
}

TEST(Observation, SimpleIndexIsTheSeedsBijection) {
  LevelMap m = parse_level_map(kLevel1, "level01.txt");
  // (x, y, z) -> 4wy + 4x + z with w = 5.
  EXPECT_EQ(simple_index(m, 2, 5, 0), 4 * 5 * 5 + 4 * 2 + 0);
  EXPECT_EQ(simple_index(m, 0, 0, 3), 3);
  EXPECT_EQ(simple_index(m, 4, 5, 3), 4 * 5 * 6 - 1);  // the largest index, w*h*4 - 1
  EXPECT_EQ(simple_index(m, -1, 5, 1), simple_index(m, 0, 5, 1));  // off the edge: clamped
}

TEST(Observation, LocalCropRotatesWithTheFacing) {
  LevelMap m = parse_level_map(kLevel1, "level01.txt");
  const float V = -1, F = 0.5f, I = 0.75f, E = 1.0f;
  float out[9];
  // At S (2,5) facing north: rows y=3, 4, 5 (two ahead first), columns x=1..3 (left to right).
  local_crop(m, 2, 5, 0, 2, 0, 1, out);
  EXPECT_EQ(std::vector<float>(out, out + 9), (std::vector<float>{I, F, I, I, F, I, I, F, I}));
  // At (0,5) facing east: ahead is +x, left is north (y-1), right is south (y+1, off the map).
  local_crop(m, 0, 5, 1, 2, 0, 1, out);
  EXPECT_EQ(std::vector<float>(out, out + 9), (std::vector<float>{F, F, V, I, I, V, F, F, V}));
  // At (1,1) facing west: ahead is -x (x=0 then off the map), left is south, right is north.
  local_crop(m, 1, 1, 3, 2, 0, 1, out);
  EXPECT_EQ(std::vector<float>(out, out + 9), (std::vector<float>{V, V, V, F, F, E, I, I, F}));
  // At (4,1) facing south with one row behind: rows y=3, 2, 1, 0; left is east (off), right west.
  float big[12];
  local_crop(m, 4, 1, 2, 2, 1, 1, big);
  EXPECT_EQ(std::vector<float>(big, big + 12), (std::vector<float>{V, F, I, V, F, I, V, F, I, V, I, F}));
}

TEST(Observation, VisualPlanesAreEachBoxsMean) {
  // Against the definition, box by box: output pixel (ox, oy) averages the frame's pixels with
  // cx + ox*cw/out_w <= x < cx + (ox+1)*cw/out_w (at least one column) and likewise in y, those
  // outside the frame as 0, rounded down; gray is (299 R + 587 G + 114 B) / 1000 of the sums.
  std::vector<std::uint8_t> rgb(37 * 23 * 3);
  std::uint32_t seed = 12345;
  for (auto& v : rgb) v = static_cast<std::uint8_t>((seed = seed * 1103515245u + 12345u) >> 24);
  struct Crop {
    int cx, cy, cw, ch, out_w, out_h;
  };
  for (const Crop c : {Crop{0, 0, 37, 23, 8, 5}, Crop{3, 2, 30, 20, 30, 20}, Crop{5, 1, 40, 30, 7, 9},
                       Crop{0, 0, 37, 23, 50, 40}, Crop{36, 22, 4, 4, 2, 2}}) {
    for (bool gray : {false, true}) {
      const size_t plane = static_cast<size_t>(c.out_w) * c.out_h;
      std::vector<std::uint8_t> got(plane * (gray ? 1 : 3));
      visual_planes(rgb.data(), 37, 23, c.cx, c.cy, c.cw, c.ch, c.out_w, c.out_h, gray, got.data());
      for (int oy = 0; oy < c.out_h; ++oy)
        for (int ox = 0; ox < c.out_w; ++ox) {
          const int x0 = c.cx + ox * c.cw / c.out_w, x1 = std::max(x0 + 1, c.cx + (ox + 1) * c.cw / c.out_w);
          const int y0 = c.cy + oy * c.ch / c.out_h, y1 = std::max(y0 + 1, c.cy + (oy + 1) * c.ch / c.out_h);
          unsigned sum[3] = {0, 0, 0};
          for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x)
              for (int k = 0; k < 3; ++k)
                if (x < 37 && y < 23) sum[k] += rgb[(static_cast<size_t>(y) * 37 + x) * 3 + k];
          const unsigned n = static_cast<unsigned>((x1 - x0) * (y1 - y0));
          const size_t at = static_cast<size_t>(oy) * c.out_w + ox;
          if (gray) {
            ASSERT_EQ(got[at], (299 * sum[0] + 587 * sum[1] + 114 * sum[2]) / (1000 * n)) << ox << "," << oy;
          } else {
            for (int k = 0; k < 3; ++k) ASSERT_EQ(got[k * plane + at], sum[k] / n) << ox << "," << oy << " " << k;
          }
        }
    }
  }
}

TEST(Observation, VisualPlanesAverageTheCropAndSplitChannels) {
  // A 4x2 frame: left half (10,20,30), right half (50,60,70); crop the right 2x2, one output pixel.
  std::vector<std::uint8_t> rgb;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x)
      for (int k = 0; k < 3; ++k) rgb.push_back(static_cast<std::uint8_t>((x < 2 ? 10 : 50) + 10 * k));
  std::uint8_t out[3];
  visual_planes(rgb.data(), 4, 2, 2, 0, 2, 2, 1, 1, false, out);
  EXPECT_EQ(out[0], 50);
  EXPECT_EQ(out[1], 60);
  EXPECT_EQ(out[2], 70);
  // Whole frame to 2x1: planes R then G then B, left pixel then right.
  std::uint8_t planes[6];
  visual_planes(rgb.data(), 4, 2, 0, 0, 4, 2, 2, 1, false, planes);
  EXPECT_EQ(std::vector<int>(planes, planes + 6), (std::vector<int>{10, 50, 20, 60, 30, 70}));
  // Grayscale: BT.601 luma of (50, 60, 70) = 0.299*50 + 0.587*60 + 0.114*70 = 58.18 -> 58.
  std::uint8_t gray;
  visual_planes(rgb.data(), 4, 2, 2, 0, 2, 2, 1, 1, true, &gray);
  EXPECT_EQ(gray, 58);
  // A crop reaching past the frame's right and bottom edges: those pixels count as black, so the
  // 2x3 box at (3, 0) averages two pixels of (50, 60, 70) over six: (16, 20, 23).
  visual_planes(rgb.data(), 4, 2, 3, 0, 2, 3, 1, 1, false, out);
  EXPECT_EQ(out[0], 100 / 6);
  EXPECT_EQ(out[1], 120 / 6);
  EXPECT_EQ(out[2], 140 / 6);
}

TEST(Observation, AudioMfccShapeAndSilenceCropping) {
  // 0.5 s of a 1 kHz tone at 44.1 kHz: 22050 samples. Frames of round(0.025 * 44100) = 1103
  // samples every round(0.0116 * 44100) = 512: 1 + ceil((22050 - 1103) / 512) = 42 rows.
  std::vector<psx::StereoSample> tone(22050);
  for (size_t i = 0; i < tone.size(); ++i) {
    auto v = static_cast<psx::s16>(8000 * std::sin(2 * M_PI * 1000 * static_cast<double>(i) / 44100));
    tone[i] = {v, v};
  }
  std::vector<float> out(64 * kMfccCoefficients);
  audio_mfcc(tone, 64, 64, out.data());
  auto row_is_zero = [&](int r) {
    for (int c = 0; c < kMfccCoefficients; ++c)
      if (out[static_cast<size_t>(r * kMfccCoefficients + c)] != 0.0f) return false;
    return true;
  };
  EXPECT_FALSE(row_is_zero(0));
  EXPECT_FALSE(row_is_zero(41));
  EXPECT_TRUE(row_is_zero(42));
  // Leading and trailing silence is cropped (seed §3.1.5), so padding changes nothing.
  std::vector<psx::StereoSample> padded(3000);
  padded.insert(padded.end(), tone.begin(), tone.end());
  padded.resize(padded.size() + 5000);
  std::vector<float> out2(64 * kMfccCoefficients);
  audio_mfcc(padded, 64, 64, out2.data());
  EXPECT_EQ(out, out2);
  // Silence alone is all zeros.
  std::vector<psx::StereoSample> quiet(10000);
  audio_mfcc(quiet, 64, 64, out2.data());
  for (float v : out2) EXPECT_EQ(v, 0.0f);
}

TEST(Observation, KindsHaveDocumentedShapes) {
  struct Case {
    const char* obs;
    std::vector<std::vector<std::int64_t>> shapes;
  } cases[] = {
      {"simple", {{1}}},
      {"local", {{11}}},  // 3x3 crop + cumulative reward + time left: the seed's 11 inputs
      {"episode", {{3}}},
      {"ram", {{2 * 1024 * 1024}}},
      {"rumble", {{2}}},
      {"visual", {{3, 60, 80}}},
      {"audio", {{64, 13}}},
      {"multimodal", {{3, 60, 80}, {3}, {64, 13}}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.obs);
    EnvConfig config;
    config.obs = c.obs;
    Env env(config);
    ASSERT_EQ(env.observation_spaces().size(), c.shapes.size());
    for (size_t i = 0; i < c.shapes.size(); ++i) EXPECT_EQ(env.observation_spaces()[i].shape, c.shapes[i]);
    const auto& obs = env.reset(1, 9, nullptr);
    ASSERT_EQ(obs.size(), c.shapes.size());
    if (std::string(c.obs) == "local") {
      // At the start: the crop of LocalCropRotatesWithTheFacing's first case, no reward yet, a
      // full clock.
      const float* v = static_cast<const float*>(obs[0].data);
      EXPECT_EQ(std::vector<float>(v, v + 11), (std::vector<float>{0.75f, 0.5f, 0.75f, 0.75f, 0.5f, 0.75f, 0.75f,
                                                                   0.5f, 0.75f, 0.0f, 1.0f}));
    }
  }
}
