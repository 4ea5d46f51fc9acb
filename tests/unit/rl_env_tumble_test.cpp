// Tumble through the environment layer (games/tumble/game.toml): every level resets into play
// with a full clock; scripted walks through levels 1 and 2 by step() end every move only once the
// game has settled (checked against the contract's own `move` and `score_target`, which the
// integration does not watch) with the seed's Table 3.3 rewards; the seed-style delimiter ends
// every kind of move soon after its true end. Expected positions, scores and rewards come from
// the test's own walk over the level map and the README's rules.
#include <gtest/gtest.h>

#include <string>

#include "core/console.h"
#include "rl/env.h"
#include "tumble_test_util.h"

using psxrl::rl::Env;
using psxrl::rl::EnvConfig;
using psxrl::rl::StepInfo;

namespace {

constexpr psx::u32 kContract = 0x80010000;
constexpr psx::u32 kMove = 0x38, kScoreTarget = 0x10, kClock = 0x14, kStateTimer = 0x64;
constexpr double kGamma = 0.9;

psx::u32 word(Env& env, psx::u32 offset) { return env.console().read32(kContract + offset); }

EnvConfig tumble(const std::string& obs = "simple") {
  EnvConfig c;
  c.obs = obs;
  c.gamma = kGamma;
  return c;
}

// "time: N" from the level file.
int level_seconds(int level) {
  char name[64];
  std::snprintf(name, sizeof name, "%s/level%02d.txt", TUMBLE_LEVELS_DIR, level);
  auto text = psx::read_file(name);
  std::string s(text.begin(), text.end());
  return std::stoi(s.substr(s.find("time: ") + 6));
}

// The test's model of a level: position and facing from the map's S and facing line, items by
// landing (README: coin 250, fruit 500, key 1000), the reward of seed Table 3.3.
struct Walk {
  tumble_test::LevelText map;
  int x = 0, y = 0, facing;
  int score = 0, keys = 0;
  Walk(int level, int facing0) : map(tumble_test::read_level(level)), facing(facing0) {
    for (int r = 0; r < static_cast<int>(map.rows.size()); ++r)
      for (int c = 0; c < static_cast<int>(map.rows[r].size()); ++c)
        if (map.rows[r][c] == 'S') x = c, y = r;
  }
  // Applies a route letter; returns the Table 3.3 reward units it earns and the action number.
  double apply(char m, int& action) {
    static const int dx[4] = {0, 1, 0, -1}, dy[4] = {-1, 0, 1, 0};
    action = m == 'F' ? 0 : m == 'R' ? 1 : 2;
    if (m == 'L') facing = (facing + 3) % 4;
    if (m == 'R') facing = (facing + 1) % 4;
    if (m != 'F') return 0;
    x += dx[facing], y += dy[facing];
    char& cell = map.rows[y][x];
    // The exit wins only once every key is held (README "Playing").
    bool win = cell == 'E' && keys == map.keys;
    double units = cell == 'c' ? 0.5 : cell == 'f' ? 0.7 : cell == 'k' ? 0.8 : win ? 1.0 : 0.0;
    score += cell == 'c' ? 250 : cell == 'f' ? 500 : cell == 'k' ? 1000 : 0;
    keys += cell == 'k';
    if (cell == 'c' || cell == 'f' || cell == 'k') cell = '#';
    return units;
  }
};

void walk_route(Env& env, int level, int facing0, const std::string& route) {
  Walk model(level, facing0);
  const int width = static_cast<int>(model.map.rows[0].size());
  for (size_t i = 0; i < route.size(); ++i) {
    SCOPED_TRACE("level " + std::to_string(level) + " move " + std::to_string(i) + " '" + route[i] + "'");
    int action = 0;
    double units = model.apply(route[i], action);
    auto r = env.step(action);
    bool last = i + 1 == route.size();
    EXPECT_EQ(word(env, kMove), 0u) << "the move had not finished when step() returned";
    EXPECT_EQ(r.info.score, model.score);
    EXPECT_EQ(word(env, kScoreTarget), static_cast<psx::u32>(model.score)) << "a count-up was still running";
    EXPECT_NEAR(r.reward, units * (1 - kGamma), 1e-12);
    EXPECT_EQ(r.terminated, last);
    EXPECT_FALSE(r.truncated);
    EXPECT_FALSE(r.info.hit_upper_bound);
    EXPECT_EQ(r.info.outcome, last ? "win" : "");
    // The seed's simple state (x, y, z) -> 4wy + 4x + z from the test's own walk.
    EXPECT_EQ(*static_cast<const std::int64_t*>(env.observation()[0].data),
              4 * width * model.y + 4 * model.x + model.facing);
  }
  EXPECT_EQ(model.score, model.map.max_score());
}

}  // namespace

TEST(EnvTumble, EveryLevelResetsIntoPlayWithAFullClock) {
  Env env(tumble());
  for (int level = 1; level <= 10; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    StepInfo info;
    env.reset(level, 1000 + level, &info);
    EXPECT_EQ(info.state, 48);  // README: state 48 playing
    EXPECT_EQ(info.level, level);
    EXPECT_EQ(info.score, 0);
    EXPECT_EQ(word(env, kStateTimer), 0u);
    EXPECT_EQ(word(env, kClock), static_cast<psx::u32>(level_seconds(level) * 60));  // 60 frames a second
    EXPECT_DOUBLE_EQ(info.time_left, level_seconds(level));
    EXPECT_EQ(info.game_frames, 1u);  // README: the level is in play one frame after the request
  }
}

TEST(EnvTumble, ScriptedWalksThroughLevels1And2SettleEveryMoveWithTable33Rewards) {
  Env env(tumble());
  env.reset(1, 1, nullptr);
  // The same routes as tumble_playthrough_test.cpp (tumble_rules_test.cpp explains them).
  walk_route(env, 1, 0, "LF" "RFFFFF" "RFF" "RFFFFF" "LF" "LFFFFF" "LFFFF");
  EXPECT_TRUE(env.episode_over());
  EXPECT_THROW(env.step(0), std::logic_error);
  env.reset(2, 2, nullptr);
  walk_route(env, 2, 1, "LLFF" "F" "RFFFFF" "RFFFFFF" "RFFFFF" "RFFFFFF");
}

TEST(EnvTumble, LosingEndsTheEpisodeWithTheLossReward) {
  Env env(tumble());
  env.reset(1, 3, nullptr);
  // Level 1's start is (2,5) facing north; two quarter turns face south, off the bottom row.
  env.step(1);
  env.step(1);
  auto r = env.step(0);
  EXPECT_TRUE(r.terminated);
  EXPECT_EQ(r.info.outcome, "lose");
  EXPECT_EQ(r.info.state, 6);  // README: 6 fallen
  EXPECT_NEAR(r.reward, -(1 - kGamma), 1e-12);
  EXPECT_NEAR(r.info.episode_reward, -(1 - kGamma), 1e-12);
}

TEST(EnvTumble, BadLevelsAndActionsAreRefused) {
  Env env(tumble());
  EXPECT_THROW(env.reset(0, 1, nullptr), std::out_of_range);
  EXPECT_THROW(env.reset(11, 1, nullptr), std::out_of_range);
  env.reset(1, 1, nullptr);
  EXPECT_THROW(env.step(4), std::out_of_range);
  EXPECT_THROW(env.step(-1), std::out_of_range);
  EnvConfig bad = tumble("pixels");
  EXPECT_THROW(Env{bad}, std::invalid_argument);
}

TEST(EnvTumble, MoveCapTruncates) {
  EnvConfig c = tumble();
  c.max_moves = 3;
  Env env(c);
  env.reset(1, 1, nullptr);
  EXPECT_FALSE(env.step(1).truncated);
  EXPECT_FALSE(env.step(1).truncated);
  auto r = env.step(1);
  EXPECT_TRUE(r.truncated);
  EXPECT_FALSE(r.terminated);
}

// The delimiter against the truth: a memory watch on the contract's `move` word gives the frame
// in which each move really ended. No move may end before it; each must end within the delay plus
// the longest effect sound's tail after the score settles (key: 0.44 s = 27 frames from landing,
// 5 frames after the key's 22-frame count-up and pause, games/tumble/tools/sfxgen.c) plus the
// delay of 4 frames and one frame for the pad: 4 + 5 + 1 + 4 = 14 frames.
TEST(EnvTumble, DelimiterEndsEveryMoveSoonAfterItsTrueEnd) {
  Env env(tumble());
  env.console().watch("move", kContract + kMove, 4);
  const struct {
    int level;
    const char* actions;  // digits: the seed's action numbers
  } runs[] = {{1, "1020300123"}, {3, "33"}, {4, "0202121"}, {7, "0000111"}};
  for (const auto& run : runs) {
    env.reset(run.level, 5, nullptr);
    env.console().take_watch_events();
    for (const char* a = run.actions; *a && !env.episode_over(); ++a) {
      SCOPED_TRACE("level " + std::to_string(run.level) + " action " + *a);
      auto r = env.step(*a - '0');
      if (r.terminated) break;
      psx::u64 end_frame = 0;
      for (const auto& e : env.console().take_watch_events())
        if (e.new_value == 0) end_frame = e.frame + 1;  // the write happened during frame e.frame
      ASSERT_NE(end_frame, 0u) << "the move never ended";
      psx::u64 extra = env.console().frames() - end_frame;
      EXPECT_LE(extra, 14u);
      EXPECT_EQ(word(env, kMove), 0u);
    }
  }
}
