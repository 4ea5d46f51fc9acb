// Memory search on a real game: Tumble's level 1 played by its demo script, with the marks a
// player would set (tests/data/memsearch/tumble_level1.marks). Using only what a player knows
// (the HUD's score and clock, when they turned, rolled or scored, which tile the ball is on,
// when the screen changed), the search must find the RAM contract's score, clock, camera angle,
// ball position and game state (games/tumble/README.md "RAM contract") in its top 3. The
// session must replay to the same RAM.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli/input_script.h"
#include "core/console.h"
#include "memsearch/marks.h"
#include "memsearch/recorder.h"
#include "memsearch/search.h"

namespace ms = psxrl::memsearch;

namespace {

const std::string kExe = PSXRL_BUILD_DIR "/games/tumble/tumble.exe";

// The contract's addresses (games/tumble/README.md): 0x80010000 + offset.
constexpr psx::u32 kState = 0x80010008, kScore = 0x8001000C, kClock = 0x80010014, kCameraAngle = 0x80010018,
                   kBallX = 0x8001001C, kBallY = 0x80010020;

class MemsearchTumble : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto presses = psxrl::cli::read_input_script(PSXRL_SOURCE_DIR "/games/tumble/demo/level1.txt");
    auto marks = ms::read_marks(PSXRL_TESTDATA_DIR "/memsearch/tumble_level1.marks");
    psx::Console console;
    ms::SessionSource source{kExe, "", "", ""};
    ms::boot_source(console, source);
    ms::Recorder rec(console, source, 60);
    size_t next_mark = 0;
    for (psx::u64 f = 0; f < 700; ++f) {
      psx::u16 held = 0;
      for (const auto& p : presses)
        if (f >= p.frame && f < p.frame + p.hold) held |= p.buttons;
      rec.run_frame(held, 0);
      for (; next_mark < marks.size() && marks[next_mark].frame == f; ++next_mark) rec.mark(marks[next_mark].label);
    }
    session_ = new ms::Session(rec.finish());
  }
  static void TearDownTestSuite() { delete session_; }

  // Where `address` ranks among the survivors (1-based), 0 if it is not in the top `n`.
  static size_t rank_of(const ms::Search& s, psx::u32 address, size_t n = 3) {
    auto top = s.ranked(n);
    for (size_t i = 0; i < top.size(); ++i)
      if (top[i].address() == address) return i + 1;
    return 0;
  }

  static ms::Session* session_;
};

ms::Session* MemsearchTumble::session_ = nullptr;

}  // namespace

// Each block is one variable's search, as a player would run it: one recording serves them all.
TEST_F(MemsearchTumble, FindsTheContractFromWhatAPlayerKnows) {
  {
    SCOPED_TRACE("ScoreFromTheValuesTheHudShowed");
    // Coins 250, fruit 500, the key 1000 (games/tumble/README.md); the demo collects, in order,
    // coin coin coin fruit coin, coin fruit coin coin coin, key: 4000 in all.
    const int kScores[] = {250, 500, 750, 1250, 1500, 1750, 2250, 2500, 2750, 3000, 4000};
    ms::Search s(*session_);
    s.apply("eq level_start 0");
    for (int i = 0; i < 11; ++i) s.apply("eq score#" + std::to_string(i + 1) + " " + std::to_string(kScores[i]));
    EXPECT_GE(rank_of(s, kScore), 1u);
  }
  {
    SCOPED_TRACE("ClockFromTheSecondsTheHudShowed");
    // Level 1 has 60 seconds; the HUD shows whole seconds left. A player reading it at each mark
    // sees 60 - (frames since the level started) / 60, give or take a second.
    std::string series;
    for (const ms::Mark& m : session_->marks) {
      if (m.frame < 57 || m.label == "complete") continue;
      double seconds = 60.0 - (static_cast<double>(m.frame) - 57.0) / 60.0;
      series += (series.empty() ? "@" : ",@") + std::to_string(m.frame) + "=" + std::to_string(std::lround(seconds));
  }
    ms::Search s(*session_);
    s.apply("tracks " + series);
    s.apply("decreased level_start score#11");
    EXPECT_GE(rank_of(s, kClock), 1u);
  }
  {
    SCOPED_TRACE("CameraAngleChangesExactlyWhenTheViewTurned");
    ms::Search s(*session_);
    s.apply("changes-at turn");
    EXPECT_GE(rank_of(s, kCameraAngle), 1u);
  }
  {
    SCOPED_TRACE("BallPositionFromTheTilesItStoodOn");
    // Tiles counted on screen (the demo's comments): start (2,5); the first coin (1,5); up column
    // 1 to (1,0); along row 0 to (3,0); down column 3 to (3,5); to (4,5); up column 4 to the key
    // at (4,0); back along row 0 to (1,0) before the exit.
    ms::Search x(*session_);
    for (const char* q : {"eq level_start 2", "eq score#1 1", "eq roll#1 1", "eq roll#2 2", "eq roll#3 3",
                          "eq score#10 3", "eq roll#4 4", "eq score#11 4", "eq roll#11 1"})
      x.apply(q);
    EXPECT_GE(rank_of(x, kBallX), 1u);
    ms::Search y(*session_);
    for (const char* q : {"eq level_start 5", "eq score#2 4", "eq score#5 1", "eq roll#1 0", "eq score#10 5",
                          "eq roll#5 4", "eq score#11 0"})
      y.apply(q);
    EXPECT_GE(rank_of(y, kBallY), 1u);
  }
  {
    SCOPED_TRACE("GameStateChangesWithTheScreens");
    ms::Search s(*session_);
    s.apply("changes-at title,select,level_start,complete");
    EXPECT_GE(rank_of(s, kState), 1u);
  }
}

TEST_F(MemsearchTumble, SessionReplaysToTheSameRam) {
  psx::Console console;
  ms::boot_source(console, session_->source);
  EXPECT_FALSE(ms::replay_session(console, *session_).has_value());
  // A session whose inputs were altered (no Start on the title) no longer replays: the check
  // can fail.
  ms::Session altered = *session_;
  for (psx::u64 f = 32; f < 34; ++f) altered.pad1[f] = 0;
  psx::Console again;
  ms::boot_source(again, altered.source);
  auto bad = ms::replay_session(again, altered);
  ASSERT_TRUE(bad.has_value());
  EXPECT_GE(*bad, 32u);
}
