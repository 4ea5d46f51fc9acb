// CD audio: XA-ADPCM decoding (psx-spx "CDROM XA Audio ADPCM Compression": sample = (nibble <<
// 12) >> shift + filtered history), the Setfilter channel selection of interleaved XA sectors,
// the 37.8 -> 44.1 kHz rate (7 output frames per 6 input samples; 18.9 kHz doubled first), and
// CD-DA samples played into the SPU's CD-input FIFO.
#include <filesystem>
#include <fstream>

#include "cdrom_test_harness.h"
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
  h.run_for(Cdrom::seek_time(150, 150) + 500);
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
  u32 at_level = 0;
  for (StereoSample s : out) {
    ASSERT_LE(s.left, 0);
    ASSERT_EQ(s.left, s.right);  // mono goes to both sides
    if (s.left == -4096) ++at_level;
  }
  EXPECT_GT(at_level, 4u * 4700);
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
  // s0 = (7 << 12) >> 12 = 7; s1 = 7 + (7 * 60 + 32) >> 6 = 7 + 7 = 14; s2 = 7 + (14 * 60 + 32) >> 6 = 20.
  u8 data[18 * 128] = {};
  data[4] = 0x1C;
  for (u32 j = 0; j < 28; ++j) data[16 + j * 4] = 0x07;
  XaAdpcm xa;
  std::vector<StereoSample> out;
  xa.decode_sector(data, 0x00, out);
  // Output frame k sits at input position 6k/7: frames 0..2 interpolate between 0, 7, 14, 20.
  ASSERT_GE(out.size(), 4u);
  EXPECT_EQ(out[0].left, 0);              // position 0: the previous (zero) sample
  EXPECT_EQ(out[1].left, 0 + 7 * 6 / 7);  // 6/7 of the way from 0 to 7
  EXPECT_EQ(out[2].left, 7 + 7 * 5 / 7);  // 12/7: 5/7 from 7 to 14
  EXPECT_EQ(out[3].left, 14 + 6 * 4 / 7); // 18/7: 4/7 from 14 to 20
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
  h.run_for(Cdrom::seek_time(150, 150) + 3 * Cdrom::sector_period(false));
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
