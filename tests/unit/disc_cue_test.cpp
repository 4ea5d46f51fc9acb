// CUE/BIN, ISO and lone-BIN opening: the track layout of good sheets (lead-in, INDEX 00/01,
// PREGAP, several files, quoted and relative names) and one precise error per broken sheet.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/disc/cue.h"
#include "core/input_error.h"

namespace psx::disc {
namespace {

namespace fs = std::filesystem;

class DiscCue : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("psxrl_cue_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "sub dir");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `count` raw sectors whose byte 100 holds `tag` and bytes 101..102 the sector's index in the file.
  std::string write_bin(const std::string& name, u32 count, u8 tag, u32 extra_bytes = 0) {
    std::vector<u8> data(count * kRawSectorSize + extra_bytes);
    for (u32 i = 0; i < count; ++i) {
      u8* s = data.data() + i * kRawSectorSize;
      s[100] = tag, s[101] = static_cast<u8>(i), s[102] = static_cast<u8>(i >> 8);
    }
    return write_file(name, data);
  }
  std::string write_file(const std::string& name, const std::vector<u8>& data) {
    fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(data.data()), data.size());
    return p.string();
  }
  std::string write_cue(const std::string& name, const std::string& text) {
    return write_file(name, std::vector<u8>(text.begin(), text.end()));
  }
  static std::string error_of(const std::function<void()>& f) {
    try {
      f();
    } catch (const DiscError& e) {
      return e.what();
    }
    return "(no error)";
  }

  fs::path dir_;
};

TEST_F(DiscCue, SingleDataTrackStartsAfterLeadIn) {
  write_bin("game data.bin", 10, 0xA1);
  auto disc = Disc::open(write_cue("game.cue", "FILE \"game data.bin\" BINARY\n  TRACK 01 MODE2/2352\n    INDEX 01 00:00:00\n"));
  ASSERT_EQ(disc->tracks().size(), 1u);
  EXPECT_EQ(disc->tracks()[0].index1, 150u);  // 00:02:00
  EXPECT_EQ(disc->tracks()[0].type, TrackType::Mode2);
  EXPECT_EQ(disc->lead_out(), 160u);
  RawSector s;
  ASSERT_TRUE(disc->read_sector(153, s));
  EXPECT_EQ(s[100], 0xA1);
  EXPECT_EQ(s[101], 3);
  EXPECT_FALSE(disc->read_sector(160, s));
  ASSERT_TRUE(disc->read_sector(10, s));  // lead-in pregap: synthesised empty Mode 2 sector
  EXPECT_TRUE(has_sync(s.data()));
  EXPECT_EQ(s[14], 0x10);
}

TEST_F(DiscCue, SeveralFilesWithIndex00AndRelativePaths) {
  write_bin("data.bin", 20, 1);
  write_bin("sub dir/t2.bin", 160, 2);
  write_bin("t3.bin", 200, 3);
  auto disc = Disc::open(write_cue("multi.cue",
                                   "REM made by a dumping tool\n"
                                   "FILE \"data.bin\" BINARY\n"
                                   "  TRACK 01 MODE2/2352\n"
                                   "    INDEX 01 00:00:00\n"
                                   "FILE \"sub dir/t2.bin\" BINARY\n"
                                   "  TRACK 02 AUDIO\n"
                                   "    FLAGS DCP\n"
                                   "    INDEX 00 00:00:00\n"
                                   "    INDEX 01 00:02:00\n"
                                   "FILE T3.BIN BINARY\n"  // case differs from the file on disk
                                   "  TRACK 03 AUDIO\n"
                                   "    INDEX 00 00:00:00\n"
                                   "    INDEX 01 00:01:00\n"));
  ASSERT_EQ(disc->tracks().size(), 3u);
  const auto& t = disc->tracks();
  EXPECT_EQ(t[1].index0, 170u);        // right after track 1's 20 sectors
  EXPECT_EQ(t[1].index1, 170u + 150);  // INDEX 01 two seconds into the file
  EXPECT_EQ(t[2].index0, 170u + 160);
  EXPECT_EQ(t[2].index1, 330u + 75);
  EXPECT_EQ(disc->lead_out(), 530u);
  RawSector s;
  ASSERT_TRUE(disc->read_sector(t[1].index1, s));
  EXPECT_EQ(s[100], 2);
  EXPECT_EQ(s[101], 150);
  ASSERT_TRUE(disc->read_sector(529, s));
  EXPECT_EQ(s[100], 3);
  EXPECT_EQ(s[101], 199);
  EXPECT_EQ(disc->track_at(t[1].index0)->number, 2);
}

TEST_F(DiscCue, OneFileManyTracksWithPregap) {
  write_bin("all.bin", 100, 9);
  auto disc = Disc::open(write_cue("all.cue",
                                   "FILE all.bin BINARY\n"
                                   "  TRACK 01 MODE1/2352\n"
                                   "    INDEX 01 00:00:00\n"
                                   "  TRACK 02 AUDIO\n"
                                   "    PREGAP 00:02:00\n"
                                   "    INDEX 01 00:00:40\n"));
  const auto& t = disc->tracks();
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].type, TrackType::Mode1);
  EXPECT_EQ(t[0].end, 190u);
  EXPECT_EQ(t[1].index0, 190u);          // the PREGAP is not in the file
  EXPECT_EQ(t[1].index1, 190u + 150);
  EXPECT_EQ(disc->lead_out(), 340u + 60);
  RawSector s;
  ASSERT_TRUE(disc->read_sector(200, s));  // inside the synthesised pregap: silence
  EXPECT_EQ(s[100], 0);
  ASSERT_TRUE(disc->read_sector(340, s));
  EXPECT_EQ(s[101], 40);
}

TEST_F(DiscCue, IsoAndLoneBin) {
  std::vector<u8> iso(20 * 2048, 0);
  iso[16 * 2048] = 1;
  memcpy(&iso[16 * 2048 + 1], "CD001", 5);
  iso[5 * 2048 + 7] = 0x77;
  auto disc = Disc::open(write_file("a.iso", iso));
  RawSector s;
  ASSERT_TRUE(disc->read_sector(155, s));
  EXPECT_TRUE(has_sync(s.data()));
  EXPECT_EQ(s[15], 2);                   // returned as Mode 2 Form 1
  EXPECT_EQ(s[kMode2DataOffset + 7], 0x77);
  // The same content without extension is recognised by its volume descriptor.
  EXPECT_EQ(Disc::open(write_file("a.img", iso))->lead_out(), 170u);

  std::vector<u8> raw(3 * kRawSectorSize, 0);
  for (u32 i = 0; i < 3; ++i) {
    write_sync_header(&raw[i * kRawSectorSize], 150 + i, 2);
    raw[i * kRawSectorSize + 30] = static_cast<u8>(0x50 + i);
  }
  auto bin = Disc::open(write_file("lone.bin", raw));
  EXPECT_EQ(bin->lead_out(), 153u);
  ASSERT_TRUE(bin->read_sector(152, s));
  EXPECT_EQ(s[30], 0x52);
}

struct BrokenSheet {
  const char* text;
  int line;
  const char* reason;
};

TEST_F(DiscCue, BrokenSheetsNameLineAndReason) {
  const BrokenSheet cases[] = {
      {"TRACK 01 MODE2/2352\n", 1, "TRACK before any FILE"},
      {"FILE \"a.bin\" BINARY\n  TRACK 01 MODE2/2336\n", 2, "unsupported track mode 'MODE2/2336'"},
      {"FILE \"a.bin\" WAVE\n", 1, "unsupported file type 'WAVE'"},
      {"FILE \"a.bin BINARY\n", 1, "unterminated quoted name"},
      {"FILE a.bin BINARY\n  TRACK 01 AUDIO\n    INDEX 01 00:60:00\n", 3, "out of range"},
      {"FILE a.bin BINARY\n  TRACK 01 AUDIO\n    INDEX 01 0:2\n", 3, "expected a time mm:ss:ff"},
      {"FILE a.bin BINARY\n  INDEX 01 00:00:00\n", 2, "INDEX before any TRACK"},
      {"FILE a.bin BINARY\n  TRACK 01 AUDIO\n  TRACK 02 AUDIO\n    INDEX 01 00:00:00\n", 2, "has no INDEX 01"},
      {"FILE a.bin BINARY\n  TRACK 01 AUDIO\n    INDEX 01 00:00:00\n  TRACK 03 AUDIO\n", 4, "out of order"},
      {"FILE a.bin BINARY\n  TRACK 01 AUDIO\n    INDEX 01 00:00:10\n    INDEX 01 00:00:20\n", 4, "out of order"},
      {"FILE a.bin BINARY\n  TRACK 01 AUDIO\n    INDEX 01 00:00:00\n    PREGAP 00:02:00\n", 4, "PREGAP must come before"},
      {"FILE a.bin BINARY\n  TRACK xx AUDIO\n", 2, "expected a track number"},
      {"FILE a.bin BINARY\n  TRACK 01 AUDIO\n    INDEX 01 00:00:00\nBOGUS 1\n", 4, "unknown command 'BOGUS'"},
      {"FILE a.bin BINARY\n", 1, "has no TRACK"},
      {"REM nothing\n", 1, "no FILE/TRACK found"},
  };
  for (const BrokenSheet& c : cases) {
    std::string err = error_of([&] { parse_cue(c.text, "bad.cue"); });
    EXPECT_NE(err.find("bad.cue:" + std::to_string(c.line) + ":"), std::string::npos) << c.text << " -> " << err;
    EXPECT_NE(err.find(c.reason), std::string::npos) << c.text << " -> " << err;
  }
}

TEST_F(DiscCue, ImageFileProblemsNameTheSheetLine) {
  std::string missing = write_cue("m.cue", "REM\nFILE \"nowhere.bin\" BINARY\n  TRACK 01 MODE2/2352\n    INDEX 01 00:00:00\n");
  std::string err = error_of([&] { Disc::open(missing); });
  EXPECT_NE(err.find("m.cue:2:"), std::string::npos) << err;
  EXPECT_NE(err.find("cannot open"), std::string::npos) << err;

  write_bin("short.bin", 4, 1, 100);
  std::string trunc = write_cue("t.cue", "FILE short.bin BINARY\n  TRACK 01 MODE2/2352\n    INDEX 01 00:00:00\n");
  err = error_of([&] { Disc::open(trunc); });
  EXPECT_NE(err.find("t.cue:1:"), std::string::npos) << err;
  EXPECT_NE(err.find("not a multiple of the 2352-byte"), std::string::npos) << err;

  write_bin("four.bin", 4, 1);
  std::string beyond = write_cue("b.cue",
                                 "FILE four.bin BINARY\n  TRACK 01 MODE2/2352\n    INDEX 01 00:00:00\n"
                                 "  TRACK 02 AUDIO\n    INDEX 01 00:01:00\n");
  err = error_of([&] { Disc::open(beyond); });
  EXPECT_NE(err.find("b.cue:"), std::string::npos) << err;
  EXPECT_NE(err.find("beyond the end"), std::string::npos) << err;

  err = error_of([&] { Disc::open(write_file("junk.bin", std::vector<u8>(5000, 0x33))); });
  EXPECT_NE(err.find("junk.bin: offset 0: not a disc image"), std::string::npos) << err;
  err = error_of([&] { Disc::open(write_file("cut.iso", std::vector<u8>(3000, 0))); });
  EXPECT_NE(err.find("not a multiple of 2048"), std::string::npos) << err;
  err = error_of([&] { Disc::open((dir_ / "absent.cue").string()); });
  EXPECT_NE(err.find("absent.cue: cannot open cue sheet"), std::string::npos) << err;
}

// #61: a folder where a file is expected is named as such (seeking to a folder's end used to
// report its size as 9223372036854775807).
TEST_F(DiscCue, AFolderWhereAnImageFileIsExpectedIsNamed) {
  fs::create_directories(dir_ / "track.bin");
  std::string sheet = write_cue("d.cue", "FILE \"track.bin\" BINARY\n  TRACK 01 MODE2/2352\n    INDEX 01 00:00:00\n");
  std::string err = error_of([&] { Disc::open(sheet); });
  EXPECT_NE(err.find("d.cue:1: "), std::string::npos) << err;
  EXPECT_NE(err.find("track.bin: is a folder, expected an image file"), std::string::npos) << err;
  EXPECT_EQ(err.find("9223372036854775807"), std::string::npos) << err;
  err = error_of([&] { Disc::open((dir_ / "sub dir").string()); });
  EXPECT_NE(err.find("sub dir: is a folder, expected a disc image"), std::string::npos) << err;
}

// #61: read_file (EXEs, BIOS images, states, manifests) names a folder instead of passing on
// libstdc++'s "basic_filebuf::underflow error reading the file: Is a directory".
TEST_F(DiscCue, ReadFileRefusesAFolderByName) {
  try {
    psx::read_file((dir_ / "sub dir").string());
    FAIL();
  } catch (const psx::InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir_ / "sub dir").string() + ": is a folder, expected a file");
  }
}

}  // namespace
}  // namespace psx::disc
