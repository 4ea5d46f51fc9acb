// Audio capture cropping and termination (seed §2.5), SPU-side capture and WAV files.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "spu/capture.h"
#include "spu/wav.h"
#include "spu_test_util.h"
#include "temp_files.h"

using namespace psx;
using namespace psx::spu;

namespace {
void feed(AudioCapture& c, s16 v, int n) {
  for (int i = 0; i < n; ++i) c.push({v, static_cast<s16>(-v)});
}
}  // namespace

TEST(SpuCapture, EarlyCroppingTerminationAndLateCropping) {
  AudioCapture c;
  c.start({1000, 50, 10});  // threshold 1000, stop after 50 quiet samples, keep 10 after the last loud
  feed(c, 0, 100);
  feed(c, 999, 5);  // below threshold: still waiting
  EXPECT_EQ(c.state(), AudioCapture::State::WaitingForSound);
  EXPECT_TRUE(c.samples().empty());
  feed(c, 1000, 3);  // first loud sample starts the recording
  feed(c, 10, 20);
  feed(c, -3000, 1);  // loud (right channel +3000)
  feed(c, 5, 49);
  EXPECT_EQ(c.state(), AudioCapture::State::Recording);
  feed(c, 5, 1);  // the 50th quiet sample ends it
  EXPECT_EQ(c.state(), AudioCapture::State::Finished);
  feed(c, 20000, 10);  // ignored once finished
  auto rec = c.stop();
  // 3 loud + 20 quiet + 1 loud + 10 tail = 34 samples.
  ASSERT_EQ(rec.size(), 34u);
  EXPECT_EQ(rec[0].left, 1000);
  EXPECT_EQ(rec[23].left, -3000);
  EXPECT_EQ(rec[33].left, 5);
  EXPECT_EQ(c.state(), AudioCapture::State::Idle);
}

TEST(SpuCapture, StopCropsAndSilenceGivesNothing) {
  AudioCapture c;
  c.start({100, 0, 2});
  feed(c, 500, 4);
  feed(c, 0, 30);
  auto rec = c.stop();
  EXPECT_EQ(rec.size(), 6u);  // 4 loud + 2 tail
  c.start({100, 0, 0});
  feed(c, 50, 1000);
  EXPECT_TRUE(c.stop().empty());
}

TEST(SpuCapture, SpuCapturesItsOutputExactly) {
  psx::test::SpuRig r;
  r.cd.push({0, 0});
  for (int i = 0; i < 5; ++i) r.cd.push({static_cast<s16>(8000 + i), 0});
  r.w16(0x1F801DAA, 0x0001);
  r.w16(0x1F801DB0, 0x7FFF);
  r.w16(0x1F801D80, 0x3FFF);
  r.spu.start_capture({1000, 3, 0});
  r.run_samples(20);
  auto rec = r.spu.stop_capture();
  // Output sample k (k >= 1) is cd * 7FFFh >> 15 * 7FFEh >> 15; the first loud one is sample 1.
  ASSERT_EQ(rec.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    const s32 cd = ((8000 + i) * 0x7FFF) >> 15;
    EXPECT_EQ(rec[i].left, (cd * 0x7FFE) >> 15) << i;
  }
  EXPECT_EQ(r.spu.pending_samples(), 20u);  // capture does not consume the output
}

TEST(SpuWav, WriteReadRoundTripAndErrors) {
  const auto dir = std::filesystem::temp_directory_path() / "psxrl_spu_wav_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "out.wav").string();
  std::vector<StereoSample> s = {{1, -1}, {32767, -32768}, {100, 200}};
  write_wav(path, s.data(), s.size());
  EXPECT_FALSE(test::temporary_files_left(path));
  EXPECT_EQ(std::filesystem::file_size(path), 44u + 12u);
  WavData w = read_wav(path);
  EXPECT_EQ(w.sample_rate, 44100u);
  EXPECT_EQ(w.channels, 2);
  ASSERT_EQ(w.samples.size(), 6u);
  EXPECT_EQ(w.samples[2], 32767);
  EXPECT_EQ(w.samples[3], -32768);

  // A truncated file names the offset of the chunk that runs past the end.
  {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream out(dir / "short.wav", std::ios::binary);
    out.write(bytes.data(), 50);
  }
  try {
    read_wav((dir / "short.wav").string());
    FAIL() << "expected WavError";
  } catch (const WavError& e) {
    EXPECT_NE(std::string(e.what()).find("offset 40"), std::string::npos) << e.what();
  }
  {
    std::ofstream out(dir / "junk.wav", std::ios::binary);
    out << "RIFX0000WAVE";
  }
  EXPECT_THROW(read_wav((dir / "junk.wav").string()), WavError);
  EXPECT_THROW(read_wav((dir / "missing.wav").string()), WavError);
  std::filesystem::remove_all(dir);
}
