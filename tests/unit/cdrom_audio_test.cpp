// CD audio: XA-ADPCM decoding (psx-spx "CDROM XA Audio ADPCM Compression": sample = (nibble <<
// 12) >> shift + filtered history), the Setfilter channel selection of interleaved XA sectors,
// the 37.8 -> 44.1 kHz zigzag resampling (7 output frames per 6 input samples; 18.9 kHz doubled
// first; details in cdrom_xa_zigzag_test.cpp), and CD-DA samples played into the SPU's CD-input
// FIFO.
#include <filesystem>
#include <fstream>

#include "cdrom_test_harness.h"
#include "cdrom_xa_reference.h"
#include "core/disc/sector.h"

namespace psx {
namespace {

using test::CdromHarness;

// One Form 2 real-time audio sector whose 18 groups use shift 0, filter 0 and every 4-bit
// sample equal to `nibble`: each decoded sample is (s16)(nibble << 12).
void xa_sector(u8* raw, u32 abs, u8 channel, u8 nibble, u8 coding) {
  std::fill(raw, raw + disc::kRawSectorSize, 0);
  disc::write_sync_header(raw, abs, 2);
  const u8 sub[4] = {1, channel, disc::kSubmodeAudio | disc::kSubmodeForm2 | disc::kSubmodeRealtime, coding};
  std::copy(sub, sub + 4, raw + 16);
  std::copy(sub, sub + 4, raw + 20);
  for (u32 g = 0; g < 18; ++g) {
    u8* group = raw + 24 + g * 128;
    for (u32 b = 16; b < 128; ++b) group[b] = static_cast<u8>(nibble | nibble << 4);
  }
  disc::finish_mode2_form2(raw);
}

// Sectors alternate channel 0 (nibble 1 = +4096) and channel 1 (nibble 0xF = -4096).
std::unique_ptr<disc::Disc> xa_disc(u32 count, u8 coding) {
  std::vector<u8> img(count * disc::kRawSectorSize);
  for (u32 n = 0; n < count; ++n)
    xa_sector(&img[n * disc::kRawSectorSize], 150 + n, n % 2, n % 2 ? 0xF : 0x1, coding);
  return disc::Disc::from_raw_sectors(std::move(img));
}

// Runs `sectors` sector periods after the seek, draining the FIFO as the SPU would (the test
// disc carries far more audio per second than a real interleaved stream).
std::vector<StereoSample> play(CdromHarness& h, u32 sectors, bool double_speed) {
  std::vector<StereoSample> out;
  h.run_for(Cdrom::seek_time(150, 150, true, double_speed) + 500);  // from Pause
  for (u32 i = 0; i < sectors; ++i) {
    h.run_for(Cdrom::sector_period(double_speed));
    while (h.fifo.size()) out.push_back(h.fifo.pop());
  }
  return out;
}

void start_xa(CdromHarness& h, u8 mode, u8 channel) {
  h.send(0x0D, {1, channel});
  h.wait();
  h.send(0x0E, {mode});
  h.wait();
  h.send(0x02, {0x00, 0x02, 0x00});
  h.wait();
  h.send(0x06);
  h.wait();
}

TEST(CdromAudio, XaFilterPlaysOnlyTheChosenChannel) {
  CdromHarness h;
  h.cd.insert_disc(xa_disc(8, 0x00));  // mono, 37.8 kHz, 4-bit
  start_xa(h, Cdrom::kModeXaAdpcm | Cdrom::kModeXaFilter | Cdrom::kModeDoubleSpeed, 1);
  std::vector<StereoSample> out = play(h, 8, true);
  // Four channel-1 sectors; 18 groups * 8 units * 28 = 4032 samples each -> 4032 * 7 / 6 = 4704.
  ASSERT_EQ(out.size(), 4u * 4704);
  // Every sample is -4096 = -32768 / 8, so each zigzag product is floor(-TableX[i] / 8); once the
  // 29 taps are full (frame 28 on) frame 7g+t is the sum of those for Table t+1.
  s32 steady[7] = {};
  for (int t = 0; t < 7; ++t)
    for (int i = 0; i < 29; ++i) steady[t] += (-4096 * test::kDocZigZag[i][t]) >> 15;
  for (size_t f = 0; f < out.size(); ++f) {
    ASSERT_EQ(out[f].left, out[f].right);  // mono goes to both sides
    if (f >= 28) {
      ASSERT_EQ(out[f].left, steady[f % 7]) << "frame " << f;
    }
  }
  EXPECT_EQ(steady[2], -3720);  // Table3: its gain 73E5h / 8000h of -4096, floored per product
  // XA sectors never reach the CPU: no INT1 was raised.
  EXPECT_EQ(h.irq.stat() & 4u, 0u);
  h.cd.io_write(0, 0, 1);
  EXPECT_EQ(h.cd.io_read(0, 1) & 0x04, 0x04u);  // ADPBUSY
}

TEST(CdromAudio, WithoutXaModeAudioSectorsAreData) {
  CdromHarness h;
  h.cd.insert_disc(xa_disc(4, 0x00));
  start_xa(h, Cdrom::kModeSectorSize, 1);
  auto r = h.wait();
  EXPECT_EQ(r.irq, 1);
  EXPECT_EQ(h.fifo.size(), 0u);
  std::vector<u8> d = h.read_data(8);
  EXPECT_EQ(d[4], 1);  // subheader file 1, channel 0
  EXPECT_EQ(d[5], 0);
}

TEST(CdromAudio, StereoHalfRateSectorLength) {
  CdromHarness h;
  // Stereo (coding bit 0) at 18.9 kHz (bit 2): 2016 samples per side, doubled to 4032, then
  // resampled to 4704 frames; the filter is off so every sector plays.
  h.cd.insert_disc(xa_disc(2, 0x05));
  start_xa(h, Cdrom::kModeXaAdpcm, 0);
  EXPECT_EQ(play(h, 2, false).size(), 2u * 4704);
}

TEST(CdromAudio, DecoderFilterFollowsTheDocumentedFormula) {
  // One group with filter 1 (60/64 of the previous sample), shift 12, nibble 7 in unit 0:
  // s0 = (7 << 12) >> 12 = 7; s1 = 7 + (7 * 60 + 32) >> 6 = 7 + 7 = 14; s2 = 7 + (14 * 60 + 32) >> 6 = 20;
  // s3 = 7 + (20 * 60 + 32) >> 6 = 26; s4 = 7 + 24 = 31; s5 = 7 + 29 = 36.
  u8 data[18 * 128] = {};
  data[4] = 0x1C;
  for (u32 j = 0; j < 28; ++j) data[16 + j * 4] = 0x07;
  XaAdpcm xa;
  std::vector<StereoSample> out;
  xa.decode_sector(data, 0x00, out);
  // The first seven frames are the zigzag of those six samples (ring buffer otherwise zero):
  // frame t = sum over the sample at distance i from p (s5 at i = 1 ... s0 at i = 6) of
  // (s * TableX[i]) >> 15.
  const s32 s[6] = {7, 14, 20, 26, 31, 36};
  ASSERT_GE(out.size(), 7u);
  for (int t = 0; t < 7; ++t) {
    s32 want = 0;
    for (int i = 1; i <= 6; ++i) want += (s[6 - i] * test::kDocZigZag[i - 1][t]) >> 15;
    EXPECT_EQ(out[t].left, want) << "Table" << t + 1;
  }
  // Tiny samples times the small outer coefficients floor to 0 or -1: Table7 has TableX[1..6] =
  // -5, +11h, -23h, +46h, -17h, -44h, giving -1 + 0 + -1 + 0 + -1 + -1 = -4.
  EXPECT_EQ(out[6].left, -4);
}

TEST(CdromAudio, CddaPlaybackAndMute) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "psxrl_cd_cdda";
  std::filesystem::create_directories(dir);
  std::vector<u8> audio(20 * disc::kRawSectorSize);
  for (size_t i = 0; i < audio.size(); i += 4) {  // left = +1000, right = -2000
    audio[i] = 0xE8, audio[i + 1] = 0x03, audio[i + 2] = 0x30, audio[i + 3] = 0xF8;
  }
  std::ofstream(dir / "a.bin", std::ios::binary).write(reinterpret_cast<char*>(audio.data()), audio.size());
  std::ofstream(dir / "a.cue") << "FILE a.bin BINARY\n TRACK 01 AUDIO\n  INDEX 01 00:00:00\n";
  CdromHarness h;
  h.cd.insert_disc(disc::Disc::open((dir / "a.cue").string()));
  h.send(0x03, {0x01});
  EXPECT_EQ(h.wait().irq, 3);
  h.run_for(Cdrom::seek_time(150, 150, true, false) + 3 * Cdrom::sector_period(false));  // from Pause
  ASSERT_EQ(h.fifo.size(), 3u * 588);  // 2352 bytes = 588 stereo 16-bit frames per sector
  StereoSample s = h.fifo.pop();
  EXPECT_EQ(s.left, 1000);
  EXPECT_EQ(s.right, -2000);
  h.send(0x0B);  // Mute
  h.wait();
  h.fifo.clear();
  h.run_for(Cdrom::sector_period(false));
  ASSERT_GT(h.fifo.size(), 0u);
  EXPECT_EQ(h.fifo.pop().left, 0);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace psx
