// Buttons and frame counts as a game sees them (issue #62), on Tumble's level-select screen: the
// highlighted level (contract word menu_level, 0x80010058) moves one step per press of RIGHT, a
// press being a down edge (games/tumble/logic/flow.c: pressed = buttons & ~previous). So the
// number of steps it moves counts the presses the game saw. Frame counts are checked against the
// frames the script and the step are known to run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/console.h"
#include "rl/env.h"
#include "tumble_manifest_util.h"

namespace fs = std::filesystem;
using psxrl::rl::Env;
using psxrl::rl::EnvConfig;

namespace {

constexpr psx::u32 kMenuLevel = 0x80010058;
constexpr int kLookRight = 1;  // Tumble's action 1: RIGHT, hold 2

// Tumble's integration, its levels started by `script` and ready on the level-select screen
// (state 56), stepped in `moves` mode ("frames" with a frame skip, or "delimited").
std::string menu_manifest(const std::string& moves) {
  std::string m = replace(tumble_manifest(), "start = \"request\"", "start = \"script\"");
  m = replace(m, "ready = { variable = \"state\", in = [48] }", "ready = { variable = \"state\", in = [56] }");
  return replace(m, "mode = \"delimited\"", moves);
}

// Writes games/tumble/{game.toml, game.lua} in a fresh temporary folder and returns an
// environment over it (the name stays "tumble", so the built program is found).
EnvConfig config_for(const std::string& name, const std::string& manifest, const std::string& script) {
  fs::path games = fs::temp_directory_path() / ("psxrl_input_" + name);
  fs::remove_all(games);
  fs::create_directories(games / "tumble");
  std::ofstream(games / "tumble" / "game.toml") << manifest;
  std::ofstream(games / "tumble" / "game.lua") << script;
  EnvConfig c;
  c.games_dir = games.string();
  c.obs = "episode";
  return c;
}

const char* kToSelect = "function start_level(level) env.press('start', 2) end\n";

}  // namespace

// Frame-skip steps press the action for its `hold` frames and release it for the rest of the
// step: three RIGHT steps are three presses (1 -> 4). A hold as long as the step keeps the
// button down across steps: one press (1 -> 2).
TEST(EnvInput, FrameSkipStepsHonourHold) {
  Env pressed(config_for("skip_hold", menu_manifest("mode = \"frames\"\nframe_skip = [6]"), kToSelect));
  pressed.reset(1, 1, nullptr);
  EXPECT_EQ(pressed.console().read32(kMenuLevel), 1u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(pressed.step(kLookRight).info.game_frames, 6u);
  EXPECT_EQ(pressed.console().read32(kMenuLevel), 4u);

  std::string held_manifest = menu_manifest("mode = \"frames\"\nframe_skip = [6]");
  held_manifest = replace(held_manifest, "buttons = [\"right\"]\nhold = 2", "buttons = [\"right\"]\nhold = 6");
  Env held(config_for("skip_held", held_manifest, kToSelect));
  held.reset(1, 1, nullptr);
  for (int i = 0; i < 3; ++i) held.step(kLookRight);
  EXPECT_EQ(held.console().read32(kMenuLevel), 2u);
}

// env.press runs its frames and a release frame: START then RIGHT twice in a row are three
// presses (title -> select, 1 -> 2 -> 3), and the reset counts all 3 x (2 + 1) frames.
TEST(EnvInput, ScriptPressesInARowAreSeparatePresses) {
  std::string script = "function start_level(level)\n  env.press('start', 2)\n  env.press('right', 2)\n"
                       "  env.press('right', 2)\nend\n";
  Env env(config_for("press_twice", menu_manifest("mode = \"frames\"\nframe_skip = [6]"), script));
  psxrl::rl::StepInfo info;
  env.reset(1, 1, &info);
  EXPECT_EQ(env.console().read32(kMenuLevel), 3u);
  EXPECT_EQ(info.game_frames, 9u);
}

// A step's frames include what after_move runs: 6 frames of frame skip + 5 of the script.
TEST(EnvInput, StepFramesIncludeTheScriptsFrames) {
  std::string script = std::string(kToSelect) + "function after_move(action) env.run_frames(5) end\n";
  Env env(config_for("after_move", menu_manifest("mode = \"frames\"\nframe_skip = [6]"), script));
  env.reset(1, 1, nullptr);
  std::uint64_t before = env.console().frames();
  auto r = env.step(kLookRight);
  EXPECT_EQ(r.info.game_frames, 11u);
  EXPECT_EQ(env.console().frames() - before, 11u);
}

// The same in delimited mode on level 1: the first move with after_move's 7 frames counts 7
// frames more than the same move without them.
TEST(EnvInput, DelimitedMoveFramesIncludeAfterMove) {
  auto first_move_frames = [](const std::string& name, const std::string& script) {
    Env env(config_for(name, tumble_manifest(), script));
    env.reset(1, 1, nullptr);
    return env.step(kLookRight).info.game_frames;
  };
  std::uint64_t plain = first_move_frames("move_plain", "");
  std::uint64_t with_script = first_move_frames("move_script", "function after_move(action) env.run_frames(7) end\n");
  EXPECT_GT(plain, 12u);  // a turn alone takes 12 frames (games/tumble/README.md "Moves")
  EXPECT_EQ(with_script, plain + 7);
}
