// psxrl play's window, recordings and headless fallback, run as a user runs them (the psxrl
// executable). PlayWindow.* need an X display: CTest runs them under xvfb-run with SDL's dummy
// sound driver (tests/frontend/CMakeLists.txt). The expected pictures are arithmetic on the
// console's own frames (each console pixel becomes a 2x2 square in a 640x480 window), the
// expected video frame counts and rates arithmetic on psx-spx's video timing.
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "test_support.h"

namespace fs = std::filesystem;
using psxrl::test::Image;
using psxrl::test::read_png;
using psxrl::test::run;

namespace {

const std::string kPsxrl = std::string(PSXRL_BUILD_DIR) + "/psxrl";

fs::path fresh_dir(const std::string& name) {
  fs::path d = fs::path(PSXRL_TEST_OUT_DIR) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(PlayWindow, ShowsTheConsolePictureAtTwiceItsSize) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  fs::path d = fresh_dir("window");
  auto r = run(kPsxrl + " play --game tumble --level 1 --frames 90 --window-screenshot " + (d / "window.png").string() +
               " --record " + (d / "frames").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("episode 1: score 0, stopped, 90 frames"), std::string::npos) << r.output;
  // The 90th frame as the console drew it (software renderer), and the window's last picture.
  Image frame = read_png(d / "frames" / "frame000090.png");
  Image window = read_png(d / "window.png");
  ASSERT_EQ(frame.width, 320u);
  ASSERT_EQ(frame.height, 240u);
  ASSERT_EQ(window.width, 640u);   // 4:3 at twice the 240 lines
  ASSERT_EQ(window.height, 480u);
  size_t lit = 0, mismatches = 0;
  for (unsigned y = 0; y < window.height; ++y)
    for (unsigned x = 0; x < window.width; ++x) {
      const unsigned char* w = window.pixel(x, y);
      const unsigned char* f = frame.pixel(x / 2, y / 2);
      mismatches += w[0] != f[0] || w[1] != f[1] || w[2] != f[2];
      lit += (w[0] | w[1] | w[2]) != 0;
    }
  EXPECT_EQ(mismatches, 0u);
  // Tumble's level view fills the screen with sky and floor: far from a black window.
  EXPECT_GT(lit, window.width * window.height / 2);
}

// --renderer gl in the window draws on SDL2's OpenGL (Mesa's GLX under xvfb) at scale 2: the
// recorded frame and the window are 640x480, and every 2x2 block's top-left pixel is the software
// renderer's picture (docs/renderer.md, "Scaling").
TEST(PlayWindow, TheOpenGLRendererDrawsTheWindowAtScale2OnSdlOpenGL) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  fs::path d = fresh_dir("window_gl");
  const std::string common = kPsxrl + " play --game tumble --level 1 --frames 90 --record ";
  auto gl = run(common + (d / "gl").string() + " --renderer gl --scale 2 --window-screenshot " +
                (d / "window.png").string());
  ASSERT_EQ(gl.code, 0) << gl.output;
  EXPECT_EQ(gl.output.find("drawing with OSMesa"), std::string::npos) << gl.output;
  auto sw = run(common + (d / "sw").string());
  ASSERT_EQ(sw.code, 0) << sw.output;
  Image frame = read_png(d / "gl" / "frame000090.png");
  Image window = read_png(d / "window.png");
  Image native = read_png(d / "sw" / "frame000090.png");
  ASSERT_EQ(frame.width, 640u);
  ASSERT_EQ(frame.height, 480u);
  ASSERT_EQ(window.width, 640u);
  ASSERT_EQ(window.height, 480u);
  size_t window_mismatches = 0, native_mismatches = 0;
  for (unsigned y = 0; y < frame.height; ++y)
    for (unsigned x = 0; x < frame.width; ++x) {
      const unsigned char *f = frame.pixel(x, y), *w = window.pixel(x, y);
      window_mismatches += f[0] != w[0] || f[1] != w[1] || f[2] != w[2];
      if (x % 2 == 0 && y % 2 == 0) {
        const unsigned char* n = native.pixel(x / 2, y / 2);
        native_mismatches += f[0] != n[0] || f[1] != n[1] || f[2] != n[2];
      }
    }
  EXPECT_EQ(window_mismatches, 0u);
  EXPECT_EQ(native_mismatches, 0u);
}

TEST(PlayWindow, RecordsAVideoWhileShowingIt) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  fs::path d = fresh_dir("window_video");
  auto r = run(kPsxrl + " play --frames 60 --record " + (d / "play.mp4").string());
  ASSERT_EQ(r.code, 0) << r.output;
  psxrl::test::VideoInfo v = psxrl::test::probe_video(d / "play.mp4");
  EXPECT_EQ(v.video_frames, 60);
  EXPECT_EQ(v.width, 320);
  EXPECT_EQ(v.height, 240);
}

// A Q-table policy trained for one episode of one move: enough to drive play.
fs::path tiny_policy() {
  // One per test process: CTest may run the window and headless tests at once.
  static struct Folder {
    fs::path d = fs::path(PSXRL_TEST_OUT_DIR) / ("tiny_policy_" + std::to_string(getpid()));
    ~Folder() { fs::remove_all(d); }
  } folder;
  const fs::path& d = folder.d;
  if (fs::exists(d / "checkpoint.psxrl")) return d;
  fs::remove_all(d);
  auto r = run(kPsxrl + " train --agent q --episodes 1 --test-every 1 --max-moves 1 --quiet --out " + d.string());
  EXPECT_EQ(r.code, 0) << r.output;
  return d;
}

// The window only displays: a policy plays the same episode in it as headless.
TEST(PlayWindow, APolicyPlaysTheSameInTheWindowAsHeadless) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  std::string args = " play --policy " + tiny_policy().string() + " --episodes 2 --max-moves 6";
  auto window = run(kPsxrl + args);
  auto headless = run(kPsxrl + args + " --headless");
  ASSERT_EQ(window.code, 0) << window.output;
  ASSERT_EQ(headless.code, 0) << headless.output;
  EXPECT_NE(headless.output.find("episode 2: score"), std::string::npos) << headless.output;
  EXPECT_EQ(window.output, headless.output);
}

// Reads 16-bit little-endian samples from `path` after `skip` header bytes, leaving out zeros.
std::vector<std::int16_t> sound_samples(const fs::path& path, size_t skip) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(static_cast<std::streamoff>(skip));
  std::vector<std::int16_t> out;
  unsigned char b[2];
  while (in.read(reinterpret_cast<char*>(b), 2))
    if (std::int16_t v = static_cast<std::int16_t>(b[0] | b[1] << 8)) out.push_back(v);
  return out;
}

// The window's sound is the SPU's, sample for sample: SDL's "disk" audio driver writes what the
// device plays to a file, which must hold the recorded audio.wav's sound in order. Silence is left
// out of both (the device plays silence whenever its queue runs dry), and what was still queued
// when play ended is never played.
TEST(PlayWindow, TheSpeakerGetsTheConsolesSoundSampleForSample) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  fs::path d = fresh_dir("window_sound");
  auto r = run("SDL_AUDIODRIVER=disk SDL_DISKAUDIOFILE=" + (d / "device.raw").string() + " " + kPsxrl +
               " play --policy " + tiny_policy().string() + " --frames 300 --record " + (d / "frames").string());
  ASSERT_EQ(r.code, 0) << r.output;
  std::vector<std::int16_t> recorded = sound_samples(d / "frames" / "audio.wav", 44);  // after the WAV header
  std::vector<std::int16_t> played = sound_samples(d / "device.raw", 0);
  ASSERT_GT(recorded.size(), 1000u) << "the policy's moves make sounds in Tumble";
  EXPECT_GT(played.size(), recorded.size() / 2);
  ASSERT_LE(played.size(), recorded.size());
  EXPECT_TRUE(std::equal(played.begin(), played.end(), recorded.begin()));
}

TEST(PlayHeadless, Mp4HoldsEveryNthFrameAtTheConsoleRateWithItsSound) {
  fs::path d = fresh_dir("mp4");
  fs::path policy = tiny_policy();
  auto r = run(kPsxrl + " play --headless --policy " + policy.string() +
               " --episodes 5 --frames 120 --record-every 2 --record " + (d / "play.mp4").string());
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_FALSE(fs::exists(d / "play.mp4.tmp"));
  psxrl::test::VideoInfo v = psxrl::test::probe_video(d / "play.mp4");
  // 120 frames shown, 1 picture in 2 kept: 60 pictures of Tumble's 320x240 display.
  EXPECT_EQ(v.video_frames, 60);
  EXPECT_EQ(v.width, 320);
  EXPECT_EQ(v.height, 240);
  // psx-spx "GPU Timings": NTSC frames are 263 lines of 3413 video clock cycles at 53.693175 MHz,
  // 59.817 frames per second; every second frame gives 29.909 pictures per second.
  double fps = 53693175.0 / (3413.0 * 263.0);
  EXPECT_NEAR(v.frame_rate, fps / 2, 1e-6);
  EXPECT_EQ(v.video_codec == "h264" || v.video_codec == "mpeg4", true) << v.video_codec;
  // The sound: 44.1 kHz stereo AAC lasting the 120 frames (the encoder adds at most one
  // 1024-sample frame of padding).
  EXPECT_EQ(v.audio_codec, "aac");
  EXPECT_EQ(v.sample_rate, 44100);
  EXPECT_EQ(v.channels, 2);
  EXPECT_NEAR(v.audio_seconds, 120 / fps, 1024.0 / 44100 + 1e-3);
}

TEST(PlayHeadless, WithoutADisplayPlayFallsBackToHeadlessAndSaysSo) {
  fs::path policy = tiny_policy();
  auto r = run("env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER " + kPsxrl + " play --policy " + policy.string() +
               " --frames 30");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("no display (DISPLAY and WAYLAND_DISPLAY are not set): playing headless"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("episode 1: score"), std::string::npos) << r.output;
}

TEST(PlayHeadless, HumanPlayWithoutADisplayIsRefused) {
  auto r = run("env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER " + kPsxrl + " play --game tumble");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("human play needs a window: no display"), std::string::npos) << r.output;
}

// DISPLAY naming an X server that is not there (#61): SDL falls back to its invisible offscreen
// driver rather than failing, so play must ask which driver it got. No server listens on :4242
// (xvfb-run -a numbers its displays from :99).
const std::string kUnreachableDisplay = "env -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER DISPLAY=:4242 ";

TEST(PlayHeadless, HumanPlayWithAnUnreachableDisplayIsRefused) {
  auto r = run(kUnreachableDisplay + kPsxrl + " play --game tumble --frames 30");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("human play needs a window: "), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("episode 1"), std::string::npos) << r.output;
}

TEST(PlayHeadless, PolicyPlayWithAnUnreachableDisplayFallsBackToHeadless) {
  auto r = run(kUnreachableDisplay + kPsxrl + " play --policy " + tiny_policy().string() + " --frames 30");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find(": playing headless"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("episode 1: score"), std::string::npos) << r.output;
}

TEST(PlayHeadless, PngFoldersHoldEveryNthFrameAndTheSound) {
  fs::path d = fresh_dir("png");
  auto r = run(kPsxrl + " play --headless --policy " + tiny_policy().string() +
               " --frames 30 --record-every 3 --record " +
               (d / "frames").string());
  ASSERT_EQ(r.code, 0) << r.output;
  // Frames 1, 4, ..., 28: 10 pictures, named by the frame they show.
  size_t pngs = 0;
  for (const auto& e : fs::directory_iterator(d / "frames")) pngs += e.path().extension() == ".png";
  EXPECT_EQ(pngs, 10u);
  EXPECT_TRUE(fs::exists(d / "frames" / "frame000028.png"));
  EXPECT_FALSE(fs::exists(d / "frames" / "frame000030.png"));
  // audio.wav: a 44-byte header and 4 bytes per stereo sample (44100 Hz x 30 frames / 59.817 Hz).
  double seconds = (static_cast<double>(fs::file_size(d / "frames" / "audio.wav")) - 44) / 4 / 44100;
  EXPECT_NEAR(seconds, 30 * 3413.0 * 263.0 / 53693175.0, 4.0 / 44100);
}

TEST(PlayHeadless, AnUnwritableRecordingIsRefusedBeforePlaying) {
  auto r = run(kPsxrl + " play --headless --policy " + tiny_policy().string() + " --record /nonexistent-dir/x.mp4");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("/nonexistent-dir/x.mp4: cannot create the video file"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("episode 1"), std::string::npos) << r.output;
}

}  // namespace
