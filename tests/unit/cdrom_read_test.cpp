// Setloc + ReadN/ReadS of known sectors (contents through the data FIFO and DMA, 0x800 and 0x924
// sector sizes), sector intervals at single and double speed (75 and 150 sectors per second of
// the 33.8688 MHz clock), seek time growing with distance, XA-ADPCM channel filtering, CD-DA
// playback, and a save-state round trip in the middle of a read.
#include "cdrom_test_harness.h"
#include "core/disc/sector.h"

namespace psx {
namespace {

using test::bytes;
using test::CdromHarness;

// Raw Mode 2 Form 1 sectors from 00:02:00; byte k of sector n's data is (n + k) & 0xFF, and
// data bytes 0..3 hold n.
std::unique_ptr<disc::Disc> pattern_disc(u32 count) {
  std::vector<u8> img(count * disc::kRawSectorSize);
  for (u32 n = 0; n < count; ++n) {
    u8 data[disc::kDataSectorSize];
    for (u32 k = 0; k < disc::kDataSectorSize; ++k) data[k] = static_cast<u8>(n + k);
    for (u32 k = 0; k < 4; ++k) data[k] = static_cast<u8>(n >> (8 * k));
    const u8 sub[4] = {0, 0, disc::kSubmodeData, 0};
    disc::build_mode2_form1(&img[n * disc::kRawSectorSize], n + 150, sub, data);
  }
  return disc::Disc::from_raw_sectors(std::move(img));
}

std::vector<u8> msf_bcd(u32 abs) {
  disc::Msf m = disc::Msf::from_sectors(abs);
  return {disc::to_bcd(m.minute), disc::to_bcd(m.second), disc::to_bcd(m.sector)};
}

u32 le32(const std::vector<u8>& v, size_t o) { return v[o] | v[o + 1] << 8 | v[o + 2] << 16 | static_cast<u32>(v[o + 3]) << 24; }

TEST(CdromRead, SetlocReadNDeliversSectorsInOrder) {
  CdromHarness h;
  h.cd.insert_disc(pattern_disc(400));
  h.send(0x02, msf_bcd(150 + 100));  // logical block 100
  EXPECT_EQ(h.wait().irq, 3);
  h.send(0x06);
  auto ack = h.wait();
  EXPECT_EQ(ack.irq, 3);
  Cycles last = 0;
  for (u32 n = 100; n < 104; ++n) {
    auto r = h.wait();
    ASSERT_EQ(r.irq, 1) << "sector " << n;
    EXPECT_EQ(r.bytes, bytes({0x22}));  // motor on, reading
    std::vector<u8> d = h.read_data(disc::kDataSectorSize);
    EXPECT_EQ(le32(d, 0), n);
    EXPECT_EQ(d[1000], static_cast<u8>(n + 1000));
    EXPECT_EQ(d[2047], static_cast<u8>(n + 2047));
    if (last) {
      EXPECT_EQ(r.at - last, 33868800u / 75);  // single speed: 75 sectors per second
    }
    last = r.at;
  }
  h.send(0x09);  // Pause: INT3 still shows reading, INT2 the drive at rest
  auto p3 = h.wait();
  // Sectors already under way may still arrive (INT1); a drive that never pauses would send them
  // for ever, so at most 100 are skipped.
  for (int i = 0; i < 100 && p3.irq == 1; ++i) p3 = h.wait();
  EXPECT_EQ(p3.irq, 3) << "Pause's first response (INT1: still sending sectors, 0: no interrupt)";
  auto p2 = h.wait();
  EXPECT_EQ(p2.irq, 2);
  EXPECT_EQ(p2.bytes, bytes({0x02}));
}

TEST(CdromRead, DoubleSpeedWholeSectorsAndDma) {
  CdromHarness h;
  h.cd.insert_disc(pattern_disc(50));
  h.send(0x0E, {0xA0});  // double speed, 0x924-byte sectors
  h.wait();
  h.send(0x02, msf_bcd(150 + 20));
  h.wait();
  h.send(0x1B);  // ReadS
  h.wait();
  auto a = h.wait();
  auto b = h.wait();
  ASSERT_EQ(a.irq, 1);
  ASSERT_EQ(b.irq, 1);
  EXPECT_EQ(b.at - a.at, 33868800u / 150);
  // The buffered sector (21): header, subheader, data, through DMA words.
  h.cd.io_write(0, 0, 1);
  h.cd.io_write(3, 0x80, 1);
  EXPECT_TRUE(h.cd.dma_request());
  std::vector<u32> words(0x924 / 4);
  h.cd.dma_read(words.data(), static_cast<u32>(words.size()));
  EXPECT_FALSE(h.cd.dma_request());
  std::vector<u8> m = msf_bcd(150 + 21);
  EXPECT_EQ(words[0], m[0] | m[1] << 8 | m[2] << 16 | 2u << 24);  // header: BCD MSF, mode 2
  EXPECT_EQ(words[1], static_cast<u32>(disc::kSubmodeData) << 16);  // subheader 00 00 08 00
  EXPECT_EQ(words[3], 21u);                                      // first data word
}

// Seek times follow Mednafen's model (see Cdrom::seek_time); the expected cycles are its
// arithmetic: distance * 33868800 / 324000 (at least 20000), plus 10160640 (300 ms) from 2250
// sectors on, else 1237952 (double speed) or 2 * 1237952 (single speed) when leaving Pause.
TEST(CdromRead, SeekTimeModel) {
  EXPECT_EQ(Cdrom::seek_time(150, 160, true, false), 20000u + 2475904);   // 10 * 104.5 < 20000
  EXPECT_EQ(Cdrom::seek_time(160, 150, true, true), 20000u + 1237952);
  EXPECT_EQ(Cdrom::seek_time(150, 1150, false, false), 104533u);          // 1000 sectors, not paused
  EXPECT_EQ(Cdrom::seek_time(0, 2249, true, true), 235095u + 1237952);    // the last short seek
  EXPECT_EQ(Cdrom::seek_time(0, 2250, true, true), 235200u + 10160640);   // sled: no Pause wait
  EXPECT_EQ(Cdrom::seek_time(150, 15000, false, false), 1552320u + 10160640);
}

// Through the controller: a fresh disc spins with the drive idle (paused), so Setloc + ReadN
// pays the single-speed Pause wait on a short seek and the sled time on a long one; the first
// sector then takes one sector period (451584 cycles at single speed).
TEST(CdromRead, SeekTimeGrowsWithDistance) {
  auto first_sector_delay = [](u32 target) {
    CdromHarness h;
    h.cd.insert_disc(pattern_disc(20000));
    h.send(0x02, msf_bcd(target));
    h.wait();
    h.send(0x06);
    Cycles acked = h.wait().at;
    return h.wait().at - acked;
  };
  EXPECT_EQ(first_sector_delay(160), 20000u + 2475904 + 451584);           // ~87 ms
  EXPECT_EQ(first_sector_delay(15000), 1552320u + 10160640 + 451584);      // ~359 ms
}

TEST(CdromRead, GetlocLAndGetlocP) {
  CdromHarness h;
  h.cd.insert_disc(pattern_disc(100));
  h.send(0x02, msf_bcd(150 + 75 + 3));  // 00:03:03
  h.wait();
  h.send(0x06);
  h.wait();
  h.wait();
  h.send(0x10);
  auto l = h.wait();
  for (int i = 0; i < 100 && l.irq == 1; ++i) l = h.wait();  // sectors still arriving (bounded)
  ASSERT_EQ(l.irq, 3) << "GetlocL's response (INT1: still sending sectors, 0: no interrupt)";
  EXPECT_EQ(l.bytes, bytes({0x00, 0x03, 0x03, 0x02, 0x00, 0x00, 0x08, 0x00}));
  h.send(0x09);
  h.wait();
  h.send(0x11);
  auto p = h.wait();
  // Skips what the pause left (at most 100 responses); 0 means no interrupt came at all.
  for (int i = 0; i < 100 && p.irq != 3 && p.irq != 0; ++i) p = h.wait();
  ASSERT_EQ(p.irq, 3) << "GetlocP's response never came (0: no interrupt)";
  ASSERT_EQ(p.bytes.size(), 8u);
  EXPECT_EQ(p.bytes[0], 0x01);  // track 1
  EXPECT_EQ(p.bytes[1], 0x01);  // index 1
}

TEST(CdromRead, ReadingPastTheEndGivesDataEnd) {
  CdromHarness h;
  h.cd.insert_disc(pattern_disc(3));
  h.send(0x02, msf_bcd(152));
  h.wait();
  h.send(0x06);
  h.wait();
  EXPECT_EQ(h.wait().irq, 1);
  auto end = h.wait();
  EXPECT_EQ(end.irq, 4);
}

TEST(CdromRead, SaveStateMidReadGivesTheSameFuture) {
  CdromHarness a;
  a.cd.insert_disc(pattern_disc(100));
  a.send(0x02, msf_bcd(160));
  a.wait();
  a.send(0x06);
  a.wait();
  a.wait();
  StateIO w;
  a.sched.do_state(w);
  a.irq.do_state(w);
  a.cd.do_state(w);
  CdromHarness b;
  b.cd.insert_disc(pattern_disc(100));
  StateIO r(w.buffer().data(), w.buffer().size());
  b.sched.do_state(r);
  b.irq.do_state(r);
  b.cd.do_state(r);
  EXPECT_TRUE(r.at_end());
  for (int i = 0; i < 3; ++i) {
    auto x = a.wait(), y = b.wait();
    EXPECT_EQ(x.at, y.at);
    EXPECT_EQ(x.irq, y.irq);
    EXPECT_EQ(a.read_data(8), b.read_data(8));
  }
}

}  // namespace
}  // namespace psx
