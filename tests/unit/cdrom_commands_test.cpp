// CD-ROM controller command answers and interrupt sequences (psx-spx "CDROM Controller Command
// Summary", "CDROM - Response Timings"): GetID per disc kind, Test version, TOC queries, error
// responses, and the rule that a second response waits for the first to be acknowledged.
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "cdrom_test_harness.h"
#include "core/disc/iso_builder.h"

namespace psx {
namespace {

using test::bytes;
using test::CdResponse;
using test::CdromHarness;

std::unique_ptr<disc::Disc> data_disc(const std::string& license = "") {
  disc::IsoOptions o;
  o.license_text = license;
  std::string cnf = "BOOT = cdrom:\\A.EXE;1\r\n";
  return disc::Disc::from_raw_sectors(disc::build_iso({{"SYSTEM.CNF", {cnf.begin(), cnf.end()}}}, o));
}

// A data track of 300 sectors followed by an audio track of 600 sectors with a 2 s pregap.
std::unique_ptr<disc::Disc> mixed_disc(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::vector<u8> img(300 * disc::kRawSectorSize, 0);
  for (u32 i = 0; i < 300; ++i) disc::write_sync_header(&img[i * disc::kRawSectorSize], 150 + i, 2);
  std::ofstream(dir / "d.bin", std::ios::binary).write(reinterpret_cast<char*>(img.data()), img.size());
  std::vector<u8> audio(600 * disc::kRawSectorSize, 0x11);
  std::ofstream(dir / "a.bin", std::ios::binary).write(reinterpret_cast<char*>(audio.data()), audio.size());
  std::ofstream(dir / "m.cue") << "FILE d.bin BINARY\n TRACK 01 MODE2/2352\n  INDEX 01 00:00:00\n"
                                  "FILE a.bin BINARY\n TRACK 02 AUDIO\n  PREGAP 00:02:00\n  INDEX 01 00:00:00\n";
  return disc::Disc::open((dir / "m.cue").string());
}

TEST(CdromCommands, GetIdLicensedDataDisc) {
  CdromHarness h;
  h.cd.insert_disc(data_disc());
  h.send(0x1A);
  auto first = h.wait();
  EXPECT_EQ(first.irq, 3);
  EXPECT_EQ(first.bytes, bytes({0x02}));  // motor on
  auto second = h.wait();
  EXPECT_EQ(second.irq, 2);
  EXPECT_EQ(second.bytes, bytes({0x02, 0x00, 0x20, 0x00, 'S', 'C', 'E', 'A'}));
  EXPECT_EQ(second.at - first.at, Cdrom::kGetIdSecond);
}

TEST(CdromCommands, GetIdRegionFromLicenceText) {
  CdromHarness h;
  h.cd.insert_disc(data_disc("          Licensed  by          Sony Computer Entertainment Euro pe   "));
  h.send(0x1A);
  h.wait();
  EXPECT_EQ(h.wait().bytes.back(), 'E');
}

TEST(CdromCommands, GetIdNoDiscAudioDiscLidOpen) {
  CdromHarness h;
  h.send(0x1A);
  EXPECT_EQ(h.wait().irq, 3);
  auto none = h.wait();
  EXPECT_EQ(none.irq, 5);
  EXPECT_EQ(none.bytes, bytes({0x08, 0x40, 0, 0, 0, 0, 0, 0}));

  std::filesystem::path dir = std::filesystem::temp_directory_path() / "psxrl_cd_audio";
  std::filesystem::create_directories(dir);
  std::vector<u8> audio(100 * disc::kRawSectorSize, 0);
  std::ofstream(dir / "a.bin", std::ios::binary).write(reinterpret_cast<char*>(audio.data()), audio.size());
  std::ofstream(dir / "a.cue") << "FILE a.bin BINARY\n TRACK 01 AUDIO\n  INDEX 01 00:00:00\n";
  h.cd.insert_disc(disc::Disc::open((dir / "a.cue").string()));
  h.send(0x1A);
  h.wait();
  auto audio_id = h.wait();
  EXPECT_EQ(audio_id.irq, 5);
  EXPECT_EQ(audio_id.bytes, bytes({0x0A, 0x90, 0, 0, 0, 0, 0, 0}));
  std::filesystem::remove_all(dir);

  h.cd.set_lid_open(true);
  h.send(0x1A);
  auto open = h.wait();
  EXPECT_EQ(open.irq, 5);
  EXPECT_EQ(open.bytes, bytes({0x11, 0x80}));  // shell open + error, "door open"
  h.send(0x01);
  EXPECT_EQ(h.wait().bytes, bytes({0x10}));
}

TEST(CdromCommands, ShellOpenBitClearsAtGetstatAfterClosing) {
  CdromHarness h;
  h.cd.insert_disc(data_disc());
  h.cd.set_lid_open(true);
  h.cd.set_lid_open(false);
  h.send(0x01);
  EXPECT_EQ(h.wait().bytes, bytes({0x12}));  // the first Getstat still reports the opening
  h.send(0x01);
  EXPECT_EQ(h.wait().bytes, bytes({0x02}));
}

TEST(CdromCommands, TestVersionAndFirstResponseTime) {
  CdromHarness h;
  h.send(0x19, {0x20});
  auto r = h.wait();
  EXPECT_EQ(r.irq, 3);
  EXPECT_EQ(r.bytes, bytes({0x94, 0x09, 0x19, 0xC0}));
  // No disc, motor off: psx-spx "First Response", GetStat (when stopped) average 0005CF4h.
  EXPECT_EQ(r.at, 0x5CF4u);
}

TEST(CdromCommands, FirstResponseTimesWithMotorOn) {
  // ps1-tests cdrom/timing (psx.log from a console): GetStat with the motor on, 24,024 to 137,104
  // cycles, average 45,993; ReadTOC takes Init's time (psx-spx), 69,456 to 93,696.
  CdromHarness h;
  h.cd.insert_disc(data_disc());
  Cycles t0 = h.sched.now();
  h.send(0x01);
  Cycles t = h.wait().at - t0;
  EXPECT_GE(t, 24024u);
  EXPECT_LE(t, 137104u);
  t0 = h.sched.now();
  h.send(0x1E);
  t = h.wait().at - t0;
  EXPECT_GE(t, 69456u);
  EXPECT_LE(t, 93696u);
}

// Runs `n` commands `cmd` (each answered with INT3 only) and returns min, max and average of
// their acknowledge times.
struct AckTimes {
  Cycles min = ~Cycles{0}, max = 0, average = 0;
};
AckTimes ack_times(CdromHarness& h, u8 cmd, int n) {
  AckTimes a;
  Cycles total = 0;
  for (int i = 0; i < n; ++i) {
    const Cycles t0 = h.sched.now();
    h.send(cmd);
    CdResponse r = h.wait();
    EXPECT_EQ(r.irq, 3);
    const Cycles t = r.at - t0;
    a.min = std::min(a.min, t), a.max = std::max(a.max, t), total += t;
    if (cmd == 0x0A) {
      EXPECT_EQ(h.wait().irq, 2);  // Init's second response
    }
  }
  a.average = total / n;
  return a;
}

TEST(CdromCommands, AcknowledgeTimesFollowTheHardwareMeasurements) {
  // ps1-tests cdrom/timing on a console: init ack min 69,456, max 93,696, average 75,086;
  // CdlNop (GetStat) min 24,024, max 137,104, average 45,993 over 100 runs.
  CdromHarness h;
  h.cd.insert_disc(data_disc());
  AckTimes init = ack_times(h, 0x0A, 100);
  EXPECT_GE(init.min, 69456u);
  EXPECT_LE(init.max, 93696u);
  EXPECT_NEAR(static_cast<double>(init.average), 75086.0, 1500.0);
  AckTimes nop = ack_times(h, 0x01, 100);
  EXPECT_GE(nop.min, 24024u);
  EXPECT_LE(nop.max, 137104u);
  EXPECT_NEAR(static_cast<double>(nop.average), 45993.0, 3000.0);
  // Deterministic: a second console sees the same times.
  CdromHarness again;
  again.cd.insert_disc(data_disc());
  AckTimes init2 = ack_times(again, 0x0A, 100);
  EXPECT_EQ(init2.min, init.min);
  EXPECT_EQ(init2.average, init.average);
}

TEST(CdromCommands, Version1StateStartsTheAcknowledgeGeneratorAtItsSeed) {
  // docs/save-states.md: a CDRM section of version 1 (before the generator's 4 bytes, the last
  // of the body) loads, with the generator where a fresh console starts it.
  CdromHarness saved;
  saved.cd.insert_disc(data_disc());
  ack_times(saved, 0x01, 3);  // the generator has moved on
  StateIO w;
  saved.cd.do_state(w);
  std::vector<u8> v1 = w.buffer();
  ASSERT_GE(v1.size(), 16u);
  ASSERT_EQ(std::string(v1.begin(), v1.begin() + 4), "CDRM");
  v1[4] = 1;  // version 1
  u32 length = v1[8] | v1[9] << 8 | v1[10] << 16 | static_cast<u32>(v1[11]) << 24;
  length -= 4;
  for (int i = 0; i < 4; ++i) v1[8 + i] = static_cast<u8>(length >> (8 * i));
  v1.resize(v1.size() - 4);
  CdromHarness loaded, fresh;
  loaded.cd.insert_disc(data_disc());
  fresh.cd.insert_disc(data_disc());
  StateIO r(v1.data(), v1.size());
  loaded.cd.do_state(r);
  EXPECT_TRUE(r.at_end());
  const Cycles t0 = loaded.sched.now(), f0 = fresh.sched.now();
  loaded.send(0x01);
  fresh.send(0x01);
  EXPECT_EQ(loaded.wait().at - t0, fresh.wait().at - f0);
}

TEST(CdromCommands, InitWithADiscReportsTheMotorOn) {
  // ps1-tests cdrom/disc-swap and cdrom/getloc logs: after Init, "CD IRQ=2, status=0x02" and
  // "GetStat -> 0x02": the motor-on bit and nothing else.
  CdromHarness h;
  h.cd.insert_disc(data_disc());
  h.send(0x0A);
  EXPECT_EQ(h.wait().irq, 3);
  CdResponse done = h.wait();
  EXPECT_EQ(done.irq, 2);
  EXPECT_EQ(done.bytes, bytes({0x02}));
  h.send(0x01);
  EXPECT_EQ(h.wait().bytes, bytes({0x02}));
}

TEST(CdromCommands, ErrorResponses) {
  CdromHarness h;
  h.cd.insert_disc(data_disc());
  h.send(0x1F);  // no such command
  EXPECT_EQ(h.wait().bytes, bytes({0x03, 0x40}));
  h.send(0x02, {0x00, 0x02});  // Setloc needs three parameters
  auto r = h.wait();
  EXPECT_EQ(r.irq, 5);
  EXPECT_EQ(r.bytes, bytes({0x03, 0x20}));
  h.send(0x02, {0x00, 0x61, 0x00});  // second 61 is not a valid time
  EXPECT_EQ(h.wait().bytes, bytes({0x03, 0x10}));
  h.send(0x02, {0x00, 0x0A, 0x00});  // 0x0A is not BCD
  EXPECT_EQ(h.wait().bytes, bytes({0x03, 0x10}));
  h.send(0x14, {0x05});  // GetTD of a missing track
  EXPECT_EQ(h.wait().bytes, bytes({0x03, 0x10}));
  h.send(0x07);  // MotorOn while the motor turns
  EXPECT_EQ(h.wait().bytes, bytes({0x03, 0x20}));
  h.send(0x19, {0x04});  // Test sub-function this controller lacks
  EXPECT_EQ(h.wait().irq, 5);
}

TEST(CdromCommands, TocQueries) {
  CdromHarness h;
  std::filesystem::path dir = std::filesystem::temp_directory_path() / "psxrl_cd_toc";
  h.cd.insert_disc(mixed_disc(dir));
  h.send(0x13);
  EXPECT_EQ(h.wait().bytes, bytes({0x02, 0x01, 0x02}));
  h.send(0x14, {0x01});
  EXPECT_EQ(h.wait().bytes, bytes({0x02, 0x00, 0x02}));  // track 1 at 00:02
  // Track 2: 150 + 300 data sectors + 150 pregap = 600 sectors = 00:08:00.
  h.send(0x14, {0x02});
  EXPECT_EQ(h.wait().bytes, bytes({0x02, 0x00, 0x08}));
  // Lead-out: 600 + 600 = 1200 sectors = 00:16:00.
  h.send(0x14, {0x00});
  EXPECT_EQ(h.wait().bytes, bytes({0x02, 0x00, 0x16}));
  h.send(0x1E);
  EXPECT_EQ(h.wait().irq, 3);
  auto toc = h.wait();
  EXPECT_EQ(toc.irq, 2);
  std::filesystem::remove_all(dir);
}

TEST(CdromCommands, GetparamReflectsSetmodeAndSetfilter) {
  CdromHarness h;
  h.cd.insert_disc(data_disc());
  h.send(0x0E, {0xC8});
  EXPECT_EQ(h.wait().irq, 3);
  h.send(0x0D, {0x01, 0x05});
  h.wait();
  h.send(0x0F);
  EXPECT_EQ(h.wait().bytes, bytes({0x02, 0xC8, 0x00, 0x01, 0x05}));
}

TEST(CdromCommands, SecondResponseWaitsForAcknowledge) {
  CdromHarness h;
  h.cd.insert_disc(data_disc());
  h.send(0x1A);
  auto first = h.wait(200'000'000, /*ack=*/false);
  EXPECT_EQ(first.irq, 3);
  h.run_for(Cdrom::kGetIdSecond * 4);  // the INT2 is due but INT3 is not acknowledged
  h.cd.io_write(0, 1, 1);
  EXPECT_EQ(h.cd.io_read(3, 1), 0xE3u);  // still INT3; upper bits read as 1
  const Cycles acked = h.sched.now();
  h.acknowledge();
  auto second = h.wait();
  EXPECT_EQ(second.irq, 2);
  EXPECT_EQ(second.at, acked + Cdrom::kAckToNextIrq);
  EXPECT_EQ(second.bytes.size(), 8u);
}

TEST(CdromCommands, InitAndPauseSequences) {
  CdromHarness h;
  h.cd.insert_disc(data_disc());
  h.send(0x0A);
  auto a = h.wait();
  EXPECT_EQ(a.irq, 3);
  EXPECT_GE(a.at, 69456u);  // ps1-tests cdrom/timing: init ack 69,456 to 93,696 cycles
  EXPECT_LE(a.at, 93696u);
  EXPECT_EQ(h.wait().irq, 2);
  h.send(0x0F);
  EXPECT_EQ(h.wait().bytes[1], 0x20);  // Init sets mode 0x20
  h.send(0x09);  // Pause when already paused: INT3 then a quick INT2
  auto p1 = h.wait();
  auto p2 = h.wait();
  EXPECT_EQ(p1.irq, 3);
  EXPECT_EQ(p2.irq, 2);
  EXPECT_EQ(p2.at - p1.at, 0x1DF2u);  // psx-spx: Pause (when paused) average 0001DF2h
  h.send(0x08);  // Stop: the INT2 status shows the motor off
  EXPECT_EQ(h.wait().irq, 3);
  EXPECT_EQ(h.wait().bytes, bytes({0x00}));
  h.send(0x08);  // Stop when stopped: INT2 after 0001D7Bh (psx-spx average)
  auto s1 = h.wait();
  auto s2 = h.wait();
  EXPECT_EQ(s2.at - s1.at, 0x1D7Bu);
}

TEST(CdromCommands, StatusRegisterFifoBits) {
  CdromHarness h;
  h.cd.io_write(0, 0, 1);
  EXPECT_EQ(h.cd.io_read(0, 1), 0x18u);  // parameter FIFO empty and writable, index 0
  h.cd.io_write(2, 0x12, 1);
  EXPECT_EQ(h.cd.io_read(0, 1) & 0x08, 0u);
  for (int i = 0; i < 15; ++i) h.cd.io_write(2, 0, 1);
  EXPECT_EQ(h.cd.io_read(0, 1) & 0x10, 0u);  // 16 parameters: full
  h.cd.io_write(1, 0x01, 1);
  EXPECT_EQ(h.cd.io_read(0, 1) & 0x80, 0x80u);  // busy until the controller takes the command
  h.cd.io_write(0, 3, 1);
  EXPECT_EQ(h.cd.io_read(0, 1) & 3, 3u);
}

}  // namespace
}  // namespace psx
