// Audio capture cropping and termination (seed §2.5), SPU-side capture and WAV files.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "spu/adpcm.h"
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

TEST(SpuCapture, CaptureBuffersHoldCdInputAndVoices1And3) {
  // psx-spx "SPU Memory layout": 000h CD left, 400h CD right (before the CD volume), 800h voice 1
  // and C00h voice 3 (after the envelope, OUTX), 200h halfwords each, one halfword per sample at
  // the same position in all four. Two different ADPCM blocks (filter 0, shift 0: nibble 7 is
  // 7000h, nibble 8 is -8000h) make the voices' outputs distinguishable; CD frames are counted.
  psx::test::SpuRig r;
  std::vector<u8> blocks(32, 0);
  for (u32 i = 2; i < 16; ++i) blocks[i] = 0x77, blocks[16 + i] = 0x88;
  blocks[1] = blocks[17] = kAdpcmLoopEnd | kAdpcmLoopRepeat | kAdpcmLoopStart;  // each loops on itself
  r.put_ram(0x2000, blocks);
  for (u32 v : {1u, 3u}) {
    r.voice_w(v, 0x0, 0x3FFF);
    r.voice_w(v, 0x2, 0x3FFF);
    r.voice_w(v, 0x4, 0x1000);
    r.voice_w(v, 0x6, static_cast<u16>((0x2000 + (v == 3 ? 16 : 0)) / 8));
    r.voice_w(v, 0x8, 0x00FF);  // attack shift 0: full level in a few samples
    r.voice_w(v, 0xA, 0x1FC0);
  }
  r.w16(0x1F801DAA, 0xC000);  // SPU enable, unmute
  r.w16(0x1F801D88, 0x000A);  // KON voices 1 and 3
  s16 cd = 0;
  for (u32 k = 0; k < 1200; ++k) {  // past two wraps of the 200h-halfword buffers
    r.cd.push({cd, static_cast<s16>(~cd)});
    r.run_samples(1);
    const u8* ram = r.spu.ram();
    const u32 pos = k & 0x1FF;  // the sample just made wrote here
    auto at = [&](u32 buffer) { return static_cast<s16>(ram[buffer + 2 * pos] | ram[buffer + 2 * pos + 1] << 8); };
    ASSERT_EQ(at(0x000), cd) << k;
    ASSERT_EQ(at(0x400), static_cast<s16>(~cd)) << k;
    ASSERT_EQ(at(0x800), r.spu.voice(1).output) << k;
    ASSERT_EQ(at(0xC00), r.spu.voice(3).output) << k;
    cd = static_cast<s16>(cd + 77);
  }
  EXPECT_GT(r.spu.voice(1).output, 0);
  EXPECT_LT(r.spu.voice(3).output, 0);
}
