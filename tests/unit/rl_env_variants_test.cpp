// Integrations written for the test in a temporary folder, from Tumble's manifest: ALE-style
// frame stepping (frame skip in a range, sticky actions) is deterministic per seed and keeps to
// its bounds; errors in an integration's Lua script reach the user as file:line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/console.h"
#include "core/input_error.h"
#include "rl/env.h"
#include "tumble_manifest_util.h"

namespace fs = std::filesystem;
using psxrl::rl::Env;
using psxrl::rl::EnvConfig;

namespace {

// Writes games/tumble/{game.toml, game.lua} under a fresh temporary folder; returns the folder
// to use as games_dir (the integration keeps the name "tumble", so the built program is found).
std::string write_integration(const std::string& name, const std::string& manifest, const std::string& script) {
  fs::path games = fs::temp_directory_path() / ("psxrl_variant_" + name);
  fs::remove_all(games);
  fs::create_directories(games / "tumble");
  std::ofstream(games / "tumble" / "game.toml") << manifest;
  std::ofstream(games / "tumble" / "game.lua") << script;
  return games.string();
}

const char* kScript = "function on_reset(level, seed) env.set('rng', seed ~= 0 and seed or 1) end\n";

EnvConfig config_for(const std::string& games_dir) {
  EnvConfig c;
  c.games_dir = games_dir;
  c.obs = "episode";
  return c;
}

}  // namespace

TEST(EnvFrames, FrameSkipStaysInRangeAndRepeatsPerSeed) {
  std::string m = replace(tumble_manifest(), "mode = \"delimited\"", "mode = \"frames\"\nframe_skip = [2, 5]");
  std::string dir = write_integration("frames", m, kScript);
  auto run = [&](std::uint64_t seed) {
    Env env(config_for(dir));
    env.reset(1, seed, nullptr);
    std::vector<std::uint64_t> frames;
    for (int i = 0; i < 30 && !env.episode_over(); ++i) {
      auto r = env.step(i % 3 == 0 ? 1 : 2);  // turns only: the ball never falls
      EXPECT_GE(r.info.game_frames, 2u);
      EXPECT_LE(r.info.game_frames, 5u);
      frames.push_back(r.info.game_frames);
    }
    return frames;
  };
  auto a = run(11), b = run(11), c = run(12);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);  // 30 draws from 4 values: equal sequences for two seeds would be a broken generator
  EXPECT_EQ(a.size(), 30u);
}

TEST(EnvFrames, StickyActionsKeepThePreviousAction) {
  std::string base = replace(tumble_manifest(), "mode = \"delimited\"", "mode = \"frames\"\nframe_skip = [4]");
  // sticky = 1: every frame keeps the previous action, which is FORWARD (0) after a reset, so
  // asking for LOOKRIGHT never turns the ball (facing stays 0, north).
  Env always(config_for(write_integration("sticky1", replace(base, "frame_skip = [4]", "frame_skip = [4]\nsticky = 1.0"), kScript)));
  always.reset(1, 3, nullptr);
  for (int i = 0; i < 6 && !always.episode_over(); ++i) always.step(1);
  EXPECT_EQ(always.console().read32(0x80010024), 0u);
  // sticky = 0: LOOKRIGHT held for 24 frames turns the view (a turn takes 12, README "Moves").
  Env never(config_for(write_integration("sticky0", base, kScript)));
  never.reset(1, 3, nullptr);
  for (int i = 0; i < 6; ++i) never.step(1);
  EXPECT_NE(never.console().read32(0x80010024), 0u);
}

TEST(EnvScriptErrors, SyntaxErrorNamesTheScriptLine) {
  std::string dir = write_integration("syntax", tumble_manifest(), "function on_reset(level, seed)\n  env.set('rng', \nend\n");
  try {
    Env env(config_for(dir));
    FAIL() << "a broken script was accepted";
  } catch (const psx::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("game.lua:3: unexpected symbol near 'end'"), std::string::npos) << e.what();
  }
}

TEST(EnvScriptErrors, RuntimeErrorNamesTheScriptLineAndHook) {
  std::string dir = write_integration("runtime", tumble_manifest(),
                                      "function on_reset(level, seed)\n  env.set('no_such_variable', 1)\nend\n");
  Env env(config_for(dir));
  try {
    env.reset(1, 1, nullptr);
    FAIL() << "a failing script was accepted";
  } catch (const psx::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("game.lua:2: unknown variable 'no_such_variable'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(in on_reset())"), std::string::npos) << e.what();
  }
}

TEST(EnvScriptErrors, BadHookResultsAreRefused) {
  std::string dir = write_integration("outcome", tumble_manifest(), std::string(kScript) + "function outcome() return 'draw' end\n");
  Env env(config_for(dir));
  env.reset(1, 1, nullptr);
  EXPECT_THROW(env.step(1), psx::InputError);
}

// #61: the manifest's script_memory_mib limits the script's state: a script that allocates
// without end fails at its line, and the environment is left consistent (the next reset fails the
// same way, not with a follow-on error).
TEST(EnvScriptErrors, TheManifestsMemoryLimitStopsARunawayScript) {
  std::string hog = "function on_reset(level, seed)\n  local t = {}\n"
                    "  for i = 1, 1e5 do t[i] = string.rep('y', 1e5) .. i end\nend\n";
  std::string manifest = replace(tumble_manifest(), "script = \"game.lua\"", "script = \"game.lua\"\nscript_memory_mib = 3");
  std::string dir = write_integration("memhog", manifest, hog);
  Env env(config_for(dir));
  try {
    env.reset(1, 1, nullptr);
    FAIL() << "the script allocated without limit";
  } catch (const psx::InputError& e) {
    EXPECT_EQ(std::string(e.what()), dir + "/tumble/game.lua:3: memory limit (3 MiB) exceeded (in on_reset())");
  }
  try {
    env.reset(1, 1, nullptr);
    FAIL() << "the script allocated without limit";
  } catch (const psx::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("game.lua:3: memory limit (3 MiB) exceeded"), std::string::npos) << e.what();
  }
}

// The CPU core is speed only: 30 moves over several episodes under the recompiler (the default)
// give the same observations, rewards and frame counts, and end in the same console state, as
// under the interpreter, the reference.
TEST(EnvCpu, RecompilerStepsTheInterpretersEpisode) {
  EnvConfig ci;
  ci.obs = "multimodal";
  ci.cpu = "interpreter";
  EnvConfig cr = ci;
  cr.cpu = "recompiler";
  Env ei(ci), er(cr);
  auto bytes = [](const psxrl::rl::Observation& obs) {
    std::string out;
    for (const auto& part : obs) out.append(static_cast<const char*>(part.data), part.space->bytes());
    return out;
  };
  ASSERT_EQ(bytes(ei.reset(2, 5)), bytes(er.reset(2, 5)));
  for (int i = 0; i < 30; ++i) {
    if (ei.episode_over()) {
      ASSERT_TRUE(er.episode_over()) << i;
      ASSERT_EQ(bytes(ei.reset(2, i)), bytes(er.reset(2, i))) << i;
    }
    const int action = (i * 7 + 3) % ei.action_count();
    auto ri = ei.step(action);
    auto rr = er.step(action);
    EXPECT_EQ(ri.reward, rr.reward) << i;
    EXPECT_EQ(ri.terminated, rr.terminated) << i;
    EXPECT_EQ(ri.info.game_frames, rr.info.game_frames) << i;
    EXPECT_EQ(bytes(ei.observation()), bytes(er.observation())) << i;
  }
  EXPECT_EQ(er.console().cpu_mode(), psx::Console::CpuMode::Recompiler);
  EXPECT_EQ(ei.console().save_state(), er.console().save_state());
}

// A visual observation draws only the frame it shows (Env keeps pixels unobserved and asks for
// the frame at the end of each step): 25 moves give the same pictures, rewards and final state
// as a console that draws every frame as it comes.
TEST(EnvVisual, DrawingOnlyTheObservedFrameGivesTheSamePictures) {
  EnvConfig c;
  c.obs = "multimodal";
  Env lazy(c), drawn(c);
  drawn.console().set_pixels_observed(true);
  auto picture = [](const psxrl::rl::Observation& obs) {
    return std::string(static_cast<const char*>(obs[0].data), obs[0].space->bytes());
  };
  ASSERT_EQ(picture(lazy.reset(1, 3)), picture(drawn.reset(1, 3)));
  for (int i = 0; i < 25; ++i) {
    if (lazy.episode_over()) {
      ASSERT_EQ(picture(lazy.reset(1, i)), picture(drawn.reset(1, i))) << i;
    }
    const int action = (i * 5 + 1) % lazy.action_count();
    EXPECT_EQ(lazy.step(action).reward, drawn.step(action).reward) << i;
    EXPECT_EQ(picture(lazy.observation()), picture(drawn.observation())) << i;
  }
  EXPECT_EQ(lazy.console().save_state(), drawn.console().save_state());
}

TEST(EnvCpu, UnknownCoreIsRefused) {
  EnvConfig c;
  c.cpu = "jit";
  EXPECT_THROW(Env{c}, std::invalid_argument);
}
