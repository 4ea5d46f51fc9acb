// Human play through the keyboard, as a person plays: psxrl play runs in a window on a virtual X
// display (CTest runs these under xvfb-run) while xdotool presses keys in it through the XTEST
// extension. The expectations are Tumble's rules (games/tumble/README.md) and the key map of
// docs/play.md: holding Up from level 1's start rolls the ball north off the map's edge (a loss,
// state 6); Enter (Start) then X (Cross) goes from the title through level select into level 1.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_support.h"

namespace fs = std::filesystem;
using psxrl::test::run;

namespace {

const std::string kPsxrl = std::string(PSXRL_BUILD_DIR) + "/psxrl";

// Runs `play_args` (after "psxrl play") in the background, waits for its window, focuses it, runs
// the xdotool commands in `keys` (one per line; "sleep S" lines pause, "!" starts a shell command;
// $pid is play's process), waits for play to end and
// runs the commands in `after` (to let go of held keys).
psxrl::test::CommandResult play_with_keys(const fs::path& dir, const std::string& env, const std::string& play_args,
                                          const std::string& keys, const std::string& after = "") {
  fs::create_directories(dir);
  std::ofstream script(dir / "keys.sh");
  script << env << " " << kPsxrl << " play " << play_args << " > " << (dir / "play.out") << " 2>&1 &\n"
         << "pid=$!\n"
         << "timeout 30 " << PSXRL_XDOTOOL << " search --sync --name 'psxrl: ' windowfocus --sync"
         << " || { kill $pid; exit 99; }\n";
  auto commands = [&](const std::string& text) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);)
      if (line.rfind("sleep", 0) == 0) script << line << "\n";
      else if (line.rfind("!", 0) == 0) script << line.substr(1) << "\n";  // a shell command
      else script << PSXRL_XDOTOOL << " " << line << "\n";
  };
  commands(keys);
  script << "wait $pid\ncode=$?\n";
  commands(after);
  script << "cat " << (dir / "play.out") << "\nexit $code\n";
  script.close();
  return run("sh " + (dir / "keys.sh").string());
}

// Pads are read once a frame (1/60 s): a key is held for several frames to be seen, and the
// pauses between keys leave the game many frames to change screens even on a slow build.
const char* kTap = "keydown %s\nsleep 0.25\nkeyup %s\n";
std::string tap(const std::string& key) {
  char buf[96];
  std::snprintf(buf, sizeof buf, kTap, key.c_str(), key.c_str());
  return buf;
}

TEST(PlayWindow, HoldingUpRollsTheBallOffLevel1sNorthEdge) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  // Level 1 (games/tumble/levels/level01.txt): the start faces north with five floor tiles and
  // then nothing ahead; Up is held until play ends, the 3000-frame cap is never reached.
  auto r = play_with_keys(fs::path(PSXRL_TEST_OUT_DIR) / "keys_up", "", "--game tumble --level 1 --frames 3000",
                          "sleep 0.3\nkeydown Up", "keyup Up");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("episode 1: score 0, lose, "), std::string::npos) << r.output;
}

TEST(PlayWindow, EscapeQuitsAtOnce) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  auto r = play_with_keys(fs::path(PSXRL_TEST_OUT_DIR) / "keys_escape", "", "--game tumble --frames 100000",
                          "sleep 0.3\n" + tap("Escape"));
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("episode 1: score 0, stopped, "), std::string::npos) << r.output;
}

TEST(PlayWindow, PStopsTheGameUntilPressedAgain) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  // 60 frames are one second of play: paused after 0.3 s, play is still there 3 s later.
  auto r = play_with_keys(fs::path(PSXRL_TEST_OUT_DIR) / "keys_pause", "", "--game tumble --frames 60",
                          "sleep 0.3\n" + tap("p") + "sleep 3\n!kill -0 $pid && echo still playing\n" + tap("p"));
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("still playing"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("episode 1: score 0, stopped, 60 frames"), std::string::npos) << r.output;
}

// Tumble made to start its levels from save states, as Kula World does: the same program and
// script, with [levels] start = "state".
fs::path state_started_tumble(const fs::path& games) {
  fs::path dir = games / "tumble_states";
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::path src = fs::path(PSXRL_SOURCE_DIR) / "games" / "tumble";
  fs::copy_file(src / "game.lua", dir / "game.lua");
  std::ifstream in(src / "game.toml");
  std::ostringstream out;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("name = ", 0) == 0) line = "name = \"tumble_states\"";
    if (line.rfind("exe = ", 0) == 0)
      line = "exe = \"" + (fs::path(PSXRL_BUILD_DIR) / "games/tumble/tumble.exe").string() + "\"";
    if (line.rfind("start = ", 0) == 0) line = "start = \"state\"\nstate = \"{states}/level{level:02}.state\"";
    if (line.rfind("request_variable", 0) == 0) continue;
    if (line.rfind("maps = ", 0) == 0) line = "maps = \"" + (src / "levels").string() + "/level{level:02}.txt\"";
    out << line << "\n";
  }
  std::ofstream(dir / "game.toml") << out.str();
  return dir;
}

TEST(PlayWindow, F5SavesTheLevelStartStateThatTheNextPlayStartsFrom) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  fs::path dir = fs::path(PSXRL_TEST_OUT_DIR) / "keys_f5";
  fs::remove_all(dir);
  state_started_tumble(dir / "games");
  std::string env = "PSXRL_GAMES=" + (dir / "games").string();
  std::string args = "--game tumble_states --level 1 --states " + (dir / "states").string();
  // No state yet: play starts at the game's boot (the title). Start, then Cross on level select
  // starts level 1; F5 saves it; Escape quits.
  auto r = play_with_keys(dir, env, args + " --frames 100000",
                          "sleep 0.3\n" + tap("Return") + "sleep 2\n" + tap("x") + "sleep 2\nkey F5\nsleep 0.3\n" +
                              tap("Escape"));
  ASSERT_EQ(r.code, 0) << r.output;
  fs::path state = dir / "states" / "level01.state";
  EXPECT_NE(r.output.find("does not exist yet: playing from the game's boot"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("saved level 1's start state in " + state.string()), std::string::npos) << r.output;
  ASSERT_TRUE(fs::exists(state));
  EXPECT_FALSE(fs::exists(state.string() + ".tmp"));
  // The next play starts level 1 from that state: the integration's ready condition (state 48,
  // playing) holds, so the episode runs its 30 frames.
  auto again = run(env + " SDL_AUDIODRIVER=dummy " + kPsxrl + " play " + args + " --frames 30");
  ASSERT_EQ(again.code, 0) << again.output;
  EXPECT_NE(again.output.find("episode 1: score 0, stopped, 30 frames"), std::string::npos) << again.output;
}

// A corrupt level save state is a bad input file: exit 2 (#61; it was 3, "the emulated program
// failed"), naming the file. Nothing is typed, so this test does not depend on host time.
TEST(PlayWindow, ACorruptLevelStateIsBadInput) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  fs::path dir = fs::path(PSXRL_TEST_OUT_DIR) / "corrupt_state";
  fs::remove_all(dir);
  state_started_tumble(dir / "games");
  fs::create_directories(dir / "states");
  std::ofstream(dir / "states" / "level01.state") << "not a save state";
  auto r = run("PSXRL_GAMES=" + (dir / "games").string() + " SDL_AUDIODRIVER=dummy " + kPsxrl +
               " play --game tumble_states --level 1 --frames 30 --states " + (dir / "states").string());
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find((dir / "states" / "level01.state").string() + ": "), std::string::npos) << r.output;
}

}  // namespace
