// Memory search building blocks: encodings (values by arithmetic on the bytes), queries on a
// hand-made session, session folders (round trip and defects), marks files and integration
// skeletons.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "memsearch/marks.h"
#include "memsearch/search.h"
#include "memsearch/session.h"
#include "memsearch/skeleton.h"
#include "rl/integration.h"

namespace ms = psxrl::memsearch;
namespace fs = std::filesystem;

namespace {

// A session of `n` snapshots of zeroed memory, one per frame, without a console.
ms::Session blank_session(size_t n) {
  ms::Session s;
  s.frames = n;
  s.snapshot_interval = 1;
  s.pad1.assign(n, 0);
  s.pad2.assign(n, 0);
  s.start_state = {1, 2, 3};
  s.source.exe = "/nowhere/game.exe";
  for (size_t i = 0; i < n; ++i) {
    s.snapshot_frames.push_back(i);
    s.snapshots.emplace_back(ms::kSnapshotBytes, 0);
  }
  return s;
}

void put32(std::vector<psx::u8>& snap, psx::u32 off, psx::u32 v) {
  for (int i = 0; i < 4; ++i) snap[off + i] = static_cast<psx::u8>(v >> (8 * i));
}

std::string temp_dir(const std::string& name) {
  fs::path p = fs::temp_directory_path() / ("psxrl_memsearch_" + name);
  fs::remove_all(p);
  return p.string();
}

}  // namespace

TEST(MemsearchEncoding, ValuesFollowFromTheBytes) {
  std::vector<psx::u8> snap(ms::kSnapshotBytes, 0);
  snap[0] = 0x34, snap[1] = 0x12, snap[2] = 0xFF, snap[3] = 0x80;
  int64_t v = 0;
  auto value = [&](psx::u32 off, ms::Encoding e) {
    EXPECT_TRUE(ms::decode(snap, off, e, v));
    return v;
  };
  EXPECT_EQ(value(0, ms::Encoding::U16), 0x1234);
  EXPECT_EQ(value(0, ms::Encoding::U16BE), 0x3412);
  EXPECT_EQ(value(0, ms::Encoding::BCD16), 1234);
  EXPECT_EQ(value(0, ms::Encoding::U32), 0x80FF1234);
  EXPECT_EQ(value(0, ms::Encoding::S32), static_cast<int64_t>(0x80FF1234) - (int64_t{1} << 32));
  EXPECT_EQ(value(2, ms::Encoding::S8), -1);
  EXPECT_EQ(value(2, ms::Encoding::S16), 0x80FF - 0x10000);
  EXPECT_EQ(value(0, ms::Encoding::U32BE), 0x3412FF80);
  EXPECT_FALSE(ms::decode(snap, 2, ms::Encoding::BCD8, v)) << "0xFF holds no decimal digits";
  ms::Encoding e;
  EXPECT_TRUE(ms::parse_encoding("s16be", e));
  EXPECT_EQ(e, ms::Encoding::S16BE);
  EXPECT_FALSE(ms::parse_encoding("u64", e));
}

TEST(MemsearchEncoding, SnapshotOffsetsMapToRamAndScratchpad) {
  EXPECT_EQ(ms::offset_to_address(0x1000C), 0x8001000Cu);
  EXPECT_EQ(ms::offset_to_address(ms::kRamBytes + 4), 0x1F800004u);
  psx::u32 off = 0;
  ASSERT_TRUE(ms::address_to_offset(0xA001000C, off));  // KSEG1 mirror of the same byte
  EXPECT_EQ(off, 0x1000Cu);
  ASSERT_TRUE(ms::address_to_offset(0x1F8003FF, off));
  EXPECT_EQ(off, ms::kRamBytes + 0x3FF);
  EXPECT_FALSE(ms::address_to_offset(0x1F801000, off)) << "I/O ports are not in snapshots";
}

TEST(MemsearchQuery, EachQueryNarrowsTheCandidates) {
  ms::Session s = blank_session(4);
  // A score at 0x80001000 going 0, 100, 100, 350; a timer at 0x80002000 counting down.
  const psx::u32 kScore = 0x1000, kTimer = 0x2000;
  const psx::u32 score[] = {0, 100, 100, 350}, timer[] = {900, 800, 700, 600};
  for (size_t i = 0; i < 4; ++i) {
    put32(s.snapshots[i], kScore, score[i]);
    put32(s.snapshots[i], kTimer, timer[i]);
  }
  s.marks = {{1, "coin"}, {2, "turn"}, {3, "coin"}};
  ms::Search search(s, {ms::Encoding::U32, ms::Encoding::U16});
  search.apply("changes-at coin");
  // u32 and u16 at the score's offset survive; the timer also changes at 'turn'.
  ASSERT_EQ(search.count(), 2u);
  auto top = search.ranked(5);
  ASSERT_EQ(top.size(), 1u) << "the u16 is merged into the u32 at the same address";
  EXPECT_EQ(top[0].address(), 0x80001000u);
  EXPECT_EQ(top[0].encoding, ms::Encoding::U32);

  ms::Search by_value(s);
  by_value.apply("eq coin#2 350");
  by_value.apply("eq @2 100");
  EXPECT_EQ(by_value.ranked(5).at(0).address(), 0x80001000u);

  ms::Search tracked(s, {ms::Encoding::U32});
  tracked.apply("tracks start=15,coin#1=13,turn=12,coin#2=10");  // seconds seen: timer / 60
  tracked.apply("decreased start end");
  ASSERT_EQ(tracked.ranked(5).size(), 1u);
  EXPECT_EQ(tracked.ranked(5)[0].address(), 0x80002000u);
  EXPECT_GT(tracked.ranked(5)[0].score, 0.95);
}

TEST(MemsearchQuery, BadQueriesSayWhatIsWrong) {
  ms::Session s = blank_session(3);
  s.marks = {{1, "coin"}, {2, "coin"}};
  ms::Search search(s, {ms::Encoding::U8});
  auto message = [&](const std::string& q) {
    try {
      search.apply(q);
    } catch (const ms::QueryError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("eq coin 1").find("name one as coin#1..coin#2"), std::string::npos);
  EXPECT_NE(message("eq coin#3 1").find("marks only 2 frames"), std::string::npos);
  EXPECT_NE(message("eq fruit 1").find("no mark is labelled 'fruit'"), std::string::npos);
  EXPECT_NE(message("eq @7 1").find("no snapshot was taken at frame 7"), std::string::npos);
  EXPECT_NE(message("eq start ten").find("'ten' is not a whole number"), std::string::npos);
  EXPECT_NE(message("grows start end").find("unknown query 'grows'"), std::string::npos);
  EXPECT_NE(message("tracks start=1,end=2").find("three or more points"), std::string::npos);
  EXPECT_NE(message("changes-at jump").find("no mark carries"), std::string::npos);
}

TEST(MemsearchSession, FolderRoundTripKeepsEverything) {
  ms::Session s = blank_session(3);
  put32(s.snapshots[1], 0x100, 0xDEADBEEF);
  s.snapshots[2][ms::kRamBytes + 7] = 0x42;  // scratchpad
  s.pad1 = {0x10, 0, 0x4000};
  s.snapshot_interval = 1;
  s.marks = {{1, "coin"}};
  std::string dir = temp_dir("roundtrip");
  ms::write_session(s, dir);
  ms::Session r = ms::read_session(dir);
  EXPECT_EQ(r.frames, 3u);
  EXPECT_EQ(r.pad1, s.pad1);
  EXPECT_EQ(r.snapshot_frames, s.snapshot_frames);
  EXPECT_EQ(r.snapshots, s.snapshots);
  EXPECT_EQ(r.start_state, s.start_state);
  ASSERT_EQ(r.marks.size(), 1u);
  EXPECT_EQ(r.marks[0].label, "coin");
  EXPECT_EQ(r.source.exe, "/nowhere/game.exe");
  EXPECT_FALSE(fs::exists(dir + ".partial"));
  fs::remove_all(dir);
}

TEST(MemsearchSession, DefectiveFoldersNameFileAndProblem) {
  std::string dir = temp_dir("bad");
  ms::write_session(blank_session(2), dir);
  auto error_of = [&] {
    try {
      ms::read_session(dir);
    } catch (const psx::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  auto bytes = [&](const std::string& f) {
    std::ifstream in(dir + "/" + f, std::ios::binary);
    return std::vector<char>((std::istreambuf_iterator<char>(in)), {});
  };
  auto put = [&](const std::string& f, const std::vector<char>& b) {
    std::ofstream(dir + "/" + f, std::ios::binary).write(b.data(), static_cast<std::streamsize>(b.size()));
  };
  std::vector<char> snaps = bytes("snapshots.bin"), inputs = bytes("inputs.bin");
  put("snapshots.bin", std::vector<char>(snaps.begin(), snaps.begin() + 30));
  EXPECT_NE(error_of().find("snapshots.bin: offset"), std::string::npos) << error_of();
  EXPECT_NE(error_of().find("file ends early"), std::string::npos) << error_of();
  put("snapshots.bin", snaps);
  std::vector<char> wrong = inputs;
  wrong[0] = 'X';
  put("inputs.bin", wrong);
  EXPECT_NE(error_of().find("inputs.bin: offset 0: not a session input file"), std::string::npos) << error_of();
  put("inputs.bin", inputs);
  std::ofstream(dir + "/session.toml", std::ios::app) << "\n[[marks]]\nframe = 5\nlabel = \"late\"\n";
  EXPECT_NE(error_of().find("session.toml:"), std::string::npos) << error_of();
  EXPECT_NE(error_of().find("'frame' must be in 0..1, got 5"), std::string::npos) << error_of();
  fs::remove(dir + "/session.toml");
  EXPECT_NE(error_of().find("session.toml: missing"), std::string::npos) << error_of();
  fs::remove_all(dir);
  EXPECT_NE(error_of().find("not a session folder"), std::string::npos) << error_of();
}

TEST(MemsearchMarks, ParsedWithLineNumbersInErrors) {
  auto marks = ms::parse_marks("# comment\n10 coin\n\n20 turn  # trailing\n", "m.txt");
  ASSERT_EQ(marks.size(), 2u);
  EXPECT_EQ(marks[1].frame, 20u);
  EXPECT_EQ(marks[1].label, "turn");
  auto error = [](const std::string& text) {
    try {
      ms::parse_marks(text, "m.txt");
    } catch (const psx::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("10 coin\n5 coin\n"), "m.txt:2: frame 5 comes before the previous mark's frame");
  EXPECT_EQ(error("ten coin\n"), "m.txt:1: expected FRAME LABEL with FRAME a frame number, found 'ten'");
  EXPECT_EQ(error("10\n"), "m.txt:1: expected a label after the frame number");
  EXPECT_EQ(error("10 a=b\n"), "m.txt:1: a label may not contain # , = or @ (queries use them)");
  EXPECT_EQ(error("10 start\n"), "m.txt:1: 'start' and 'end' name the first and last snapshots; choose another label");
}

TEST(MemsearchSkeleton, FoundVariablesBecomeALoadableIntegration) {
  std::vector<ms::FoundVariable> vars = {ms::parse_found_variable("state=0x80010008:u32"),
                                         ms::parse_found_variable("score=0x8001000C:u32"),
                                         ms::parse_found_variable("ball_x=0x8001001C:s32")};
  ms::SessionSource src;
  src.exe = PSXRL_BUILD_DIR "/games/tumble/tumble.exe";
  std::string text = ms::integration_skeleton("found", src, vars);
  psxrl::rl::Integration g = psxrl::rl::parse_integration(text, "found/game.toml", "found", PSXRL_BUILD_DIR "/games");
  ASSERT_EQ(g.variables.size(), 3u);
  EXPECT_EQ(g.variable("score").address, 0x8001000Cu);
  EXPECT_EQ(g.state_variable, "state");
  EXPECT_EQ(g.score_variable, "score");
  EXPECT_EQ(g.actions.size(), 4u);
  EXPECT_THROW(ms::integration_skeleton("found", src, {ms::parse_found_variable("t=0x1F800000:u32")}), ms::QueryError);
  EXPECT_THROW(ms::integration_skeleton("found", src, {ms::parse_found_variable("t=0x80010000:bcd16")}), ms::QueryError);
  EXPECT_THROW(ms::parse_found_variable("score=0x8001000C"), ms::QueryError);
}
