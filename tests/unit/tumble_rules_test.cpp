// Tumble game rules (games/tumble/logic): scripted playthroughs of levels 1 and 2 reaching the
// exit with the score the maps' items add up to, and the ways to lose (falling off, spikes,
// time-out), move lengths, score count-up, view rotation and crumbling tiles.
#include <gtest/gtest.h>

#include "tumble_test_util.h"

using tumble_test::Player;
using tumble_test::read_level;

// F forward, L look left, R look right, J jump forward, H jump in place.
// Level 1 (5x6, start (2,5) facing north): west coin, column 1 north, row 0 east, column 3
// south, column 4 north to the key, row 0 west to the exit at (0,0).
static const char* kLevel1Route = "LF" "RFFFFF" "RFF" "RFFFFF" "LF" "LFFFFF" "LFFFF";
// Level 2 (7x6 ring, start (3,5) facing east): west along the bottom row, up the west side,
// east along the top, down the east side and back west to the exit at (0,5).
static const char* kLevel2Route = "LLFF" "F" "RFFFFF" "RFFFFFF" "RFFFFF" "RFFFFFF";

TEST(TumbleRules, Level1MaximumScoreIs4000FromTheMap) {
  auto level = read_level(1);
  EXPECT_EQ(level.coins, 8);
  EXPECT_EQ(level.fruit, 2);
  EXPECT_EQ(level.keys, 1);
  EXPECT_EQ(level.max_score(), 8 * 250 + 2 * 500 + 1000);
  EXPECT_EQ(level.max_score(), 4000);
}

TEST(TumbleRules, Level1ScriptedPlaythroughReachesExitWithFullScore) {
  Player p(1);
  ASSERT_EQ(p.g.pub.state, (uint32_t)STATE_PLAYING);
  EXPECT_EQ(p.g.pub.level, 1u);
  EXPECT_EQ(p.g.pub.keys_needed, 1u);
  p.script(kLevel1Route);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_SUCCESS);
  EXPECT_EQ(p.g.pub.score, (uint32_t)read_level(1).max_score());
  EXPECT_EQ(p.g.pub.keys_held, 1u);
  EXPECT_EQ(p.g.pub.ball_x, 0u);
  EXPECT_EQ(p.g.pub.ball_y, 0u);
  EXPECT_EQ(p.g.pub.levels_completed, 1u);
}

TEST(TumbleRules, Level2ScriptedPlaythroughReachesExitWithFullScore) {
  Player p(2);
  EXPECT_EQ(p.g.pub.keys_needed, 2u);
  EXPECT_EQ(p.g.pub.facing, (uint32_t)FACING_EAST);
  p.script(kLevel2Route);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_SUCCESS);
  EXPECT_EQ(p.g.pub.score, (uint32_t)read_level(2).max_score());
  EXPECT_EQ(read_level(2).max_score(), 9 * 250 + 2 * 500 + 2 * 1000);
  EXPECT_EQ(p.g.pub.ball_x, 0u);
  EXPECT_EQ(p.g.pub.ball_y, 5u);
}

TEST(TumbleRules, ExitStaysClosedWithoutAllKeys) {
  // Level 2: west twice from the start reaches the exit at (0,5) with no keys: it is floor.
  Player p(2);
  p.script("LLFFF");
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_PLAYING);
  EXPECT_EQ(p.g.pub.ball_x, 0u);
  EXPECT_EQ(p.g.pub.ball_y, 5u);
}

TEST(TumbleRules, SuccessLeadsToNextLevel) {
  Player p(1);
  p.script(kLevel1Route);
  ASSERT_EQ(p.g.pub.state, (uint32_t)STATE_SUCCESS);
  p.frames(FRAMES_SUCCESS_SCREEN);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_PLAYING);
  EXPECT_EQ(p.g.pub.level, 2u);
  EXPECT_EQ(p.g.pub.score, 0u);
}

TEST(TumbleRules, RollingOffThePlatformFallsThenGameOver) {
  // Level 2 starts at (3,5) facing east; north of it, (3,4), is a hole.
  Player p(2);
  p.script("LF");
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_FALLEN);
  EXPECT_EQ(p.g.pub.ball_x, 3u);
  EXPECT_EQ(p.g.pub.ball_y, 4u);
  p.frames(FRAMES_LOST_SCREEN - 1);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_FALLEN);
  p.frame(0);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_GAME_OVER);
  p.frames(30);
  p.frame(PAD_START);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_TITLE);
}

TEST(TumbleRules, RollingOffTheMapEdgeFalls) {
  // Level 1 start (2,5) facing north: turn round (two right turns) and roll south off row 5.
  Player p(1);
  p.script("RRF");
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_FALLEN);
  EXPECT_EQ(p.g.pub.ball_y, 6u);
}

TEST(TumbleRules, JumpingIntoAHoleFalls) {
  // Level 3 start (2,8) facing north: a jump clears the hole at (2,7) and lands on (2,6); one roll
  // on is (2,5); a jump from there passes over (2,4) and lands two tiles on, in the hole at (2,3).
  Player p(3);
  p.script("JF");
  ASSERT_EQ(p.g.pub.state, (uint32_t)STATE_PLAYING);
  EXPECT_EQ(p.g.pub.ball_y, 5u);
  p.script("J");
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_FALLEN);
  EXPECT_EQ(p.g.pub.ball_y, 3u);
}

TEST(TumbleRules, SpikesKill) {
  // Level 4 start (0,2) facing east; spikes at (4,2).
  Player p(4);
  p.script("FFF");
  ASSERT_EQ(p.g.pub.state, (uint32_t)STATE_PLAYING);
  p.script("F");
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_SPIKED);
  EXPECT_EQ(p.g.pub.ball_x, 4u);
}

TEST(TumbleRules, JumpingOverSpikesIsSafe) {
  Player p(4);
  p.script("FFFJ");
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_PLAYING);
  EXPECT_EQ(p.g.pub.ball_x, 5u);
}

TEST(TumbleRules, ClockRunsOutAfterTheLevelTime) {
  // Level 1 has 60 seconds: 3600 frames at 60 frames per second.
  Player p(1);
  EXPECT_EQ(p.g.pub.clock, 60u * 60u);
  p.frames(60 * 60 - 1);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_PLAYING);
  EXPECT_EQ(p.g.pub.clock, 1u);
  p.frame(0);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_TIME_UP);
  EXPECT_EQ(p.g.pub.clock, 0u);
  EXPECT_TRUE(p.g.pub.events & TUMBLE_EV_TIME_UP);
}
