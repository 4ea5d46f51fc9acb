// Tumble moves and screens (games/tumble/logic): move lengths (a jump outlasts a turn, rolling onto
// an item outlasts plain rolling), one move at a time, the score counting up over several frames,
// the animated view angle, crumbling tiles, the menus and the contract's request variable, and a
// search showing every level can be won within its clock.
#include <gtest/gtest.h>

#include <cstring>
#include <deque>
#include <set>
#include <string>

#include "tumble_test_util.h"

using tumble_test::Player;

TEST(TumbleMoves, LengthsFollowTheMoveAndWhatItCollects) {
  // Level 1: start (2,5) facing north onto plain floor (2,4); the coin at (1,5) lies west.
  Player p(1);
  EXPECT_EQ(p.move(PAD_UP), FRAMES_FORWARD + 1);  // press frame + FRAMES_FORWARD frames
  Player q(1);
  q.move(PAD_LEFT);
  int coin_roll = q.move(PAD_UP);
  EXPECT_EQ(coin_roll, FRAMES_FORWARD + 250 / SCORE_STEP + 2 + 1);
  EXPECT_GT(coin_roll, FRAMES_FORWARD + 1);
  Player r(1);
  int turn = r.move(PAD_RIGHT);
  int jump = r.move(PAD_CROSS);
  EXPECT_EQ(turn, FRAMES_LOOK + 1);
  EXPECT_EQ(jump, FRAMES_JUMP + 1);
  EXPECT_GT(jump, turn);
}

TEST(TumbleMoves, NewMoveOnlyAfterTheLastFinished) {
  Player p(1);
  p.frame(PAD_UP);
  EXPECT_EQ(p.g.pub.move, (uint32_t)MOVE_FORWARD);
  EXPECT_EQ(p.g.pub.move_length, (uint32_t)FRAMES_FORWARD);
  for (int i = 1; i < FRAMES_FORWARD; ++i) {
    p.frame(PAD_RIGHT);  // ignored while rolling
    EXPECT_EQ(p.g.pub.move, (uint32_t)MOVE_FORWARD);
    EXPECT_EQ(p.g.pub.move_frame, (uint32_t)i);
  }
  p.frame(PAD_RIGHT);  // the roll ends this frame and the turn starts
  EXPECT_EQ(p.g.pub.ball_y, 4u);
  EXPECT_EQ(p.g.pub.move, (uint32_t)MOVE_LOOK_RIGHT);
}

TEST(TumbleMoves, ScoreCountsUpOverSeveralFrames) {
  Player p(1);
  p.move(PAD_LEFT);
  p.frame(PAD_UP);
  p.frames(FRAMES_FORWARD - 1);
  EXPECT_EQ(p.g.pub.score, 0u);  // not landed yet
  p.frame(0);                    // lands on the coin: +50 this frame
  EXPECT_EQ(p.g.pub.score_target, 250u);
  EXPECT_EQ(p.g.pub.score, 50u);
  EXPECT_TRUE(p.g.pub.events & TUMBLE_EV_COIN);
  p.frame(0);
  EXPECT_EQ(p.g.pub.score, 100u);
  p.frames(3);
  EXPECT_EQ(p.g.pub.score, 250u);
  EXPECT_EQ(p.g.pub.move, (uint32_t)MOVE_FORWARD);  // the move lasts past the count-up
}

TEST(TumbleMoves, ViewAngleTurnsOverTheLook) {
  Player p(1);
  EXPECT_EQ(p.g.pub.camera_angle, 0u);
  p.frame(PAD_RIGHT);
  p.frames(FRAMES_LOOK / 2);
  EXPECT_EQ(p.g.pub.camera_angle, (uint32_t)(ANGLE_QUARTER / 2));
  p.frames(FRAMES_LOOK / 2);
  EXPECT_EQ(p.g.pub.camera_angle, (uint32_t)ANGLE_QUARTER);
  EXPECT_EQ(p.g.pub.facing, (uint32_t)FACING_EAST);
  p.move(PAD_LEFT);
  p.move(PAD_LEFT);
  EXPECT_EQ(p.g.pub.camera_angle, (uint32_t)(3 * ANGLE_QUARTER));
  EXPECT_EQ(p.g.pub.facing, (uint32_t)FACING_WEST);
}

TEST(TumbleMoves, CrumblingTileBreaksAfterTheBallLeavesIt) {
  // Level 5: start (3,5) facing north, crumbling tiles at (3,4) and (3,3).
  Player p(5);
  p.script("F");
  EXPECT_EQ(p.g.tile[4][3], (uint8_t)TILE_CRUMBLE);
  p.frame(PAD_UP);  // leaves (3,4)
  EXPECT_TRUE(p.g.pub.events & TUMBLE_EV_CRUMBLE_WARN);
  EXPECT_GT(p.g.rumble_frames, 0u);
  int frames = 0;
  while (p.g.tile[4][3] == TILE_CRUMBLE && frames < 200) p.frame(0), ++frames;
  EXPECT_GE(frames, FRAMES_CRUMBLE);
  EXPECT_LE(frames, FRAMES_CRUMBLE + 15);
  EXPECT_EQ(p.g.tile[4][3], (uint8_t)TILE_VOID);
  p.script("RRF");  // back onto the broken tile
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_FALLEN);
}

TEST(TumbleScreens, TitleLevelSelectAndStart) {
  Player p;
  EXPECT_EQ(p.g.pub.magic, TUMBLE_MAGIC);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_TITLE);
  EXPECT_GE(p.g.pub.level_count, 10u);
  p.frame(PAD_START);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_LEVEL_SELECT);
  p.frame(0);
  p.frame(PAD_RIGHT);
  p.frame(0);
  p.frame(PAD_RIGHT);
  p.frame(0);
  EXPECT_EQ(p.g.pub.menu_level, 3u);
  p.frame(PAD_LEFT);
  p.frame(0);
  p.frame(PAD_LEFT);
  p.frame(0);
  p.frame(PAD_LEFT);  // wraps to the last level
  EXPECT_EQ(p.g.pub.menu_level, p.g.pub.level_count);
  p.frame(0);
  p.frame(PAD_CROSS);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_PLAYING);
  EXPECT_EQ(p.g.pub.level, p.g.pub.level_count);
}

TEST(TumbleScreens, LevelStartedByCrossWaitsForItsRelease) {
  // README: a level started from a menu takes no move until every button is up, so holding the
  // confirming Cross (JUMP in play) or pressing Up with it does nothing until the pad is let go.
  Player p;
  p.frame(PAD_START);
  p.frame(0);
  p.frame(PAD_CROSS);
  ASSERT_EQ(p.g.pub.state, (uint32_t)STATE_PLAYING);
  p.frames(5, PAD_CROSS);
  EXPECT_EQ(p.g.pub.move, (uint32_t)MOVE_NONE);
  p.frame(PAD_UP);
  EXPECT_EQ(p.g.pub.move, (uint32_t)MOVE_NONE);
  p.frame(0);
  p.frame(PAD_UP);
  EXPECT_EQ(p.g.pub.move, (uint32_t)MOVE_FORWARD);
}

TEST(TumbleScreens, RequestVariableStartsALevelFromAnyScreen) {
  Player p;
  p.g.pub.request_level = 7;
  p.frame(0);
  EXPECT_EQ(p.g.pub.state, (uint32_t)STATE_PLAYING);
  EXPECT_EQ(p.g.pub.level, 7u);
  EXPECT_EQ(p.g.pub.request_level, 0u);
  p.g.pub.request_level = 99;  // no such level: ignored and cleared
  p.frame(0);
  EXPECT_EQ(p.g.pub.level, 7u);
  EXPECT_EQ(p.g.pub.request_level, 0u);
  p.script("F");
  p.g.pub.request_level = 1;  // restarts mid-level
  p.frame(0);
  EXPECT_EQ(p.g.pub.level, 1u);
  EXPECT_EQ(p.g.pub.clock, 60u * 60u);
}

// Breadth-first search over moves in the pure rules: the shortest route (in frames it is
// at least the number of moves * the shortest move) must win each level before its clock ends.
static int shortest_win_frames(int level) {
  Player start(level);
  struct Node {
    Game g;
    int frames;
  };
  std::deque<Node> queue{{start.g, 0}};
  std::set<std::string> seen;
  const uint32_t buttons[] = {PAD_UP, PAD_LEFT, PAD_RIGHT, PAD_CROSS | PAD_UP};
  while (!queue.empty()) {
    Node n = queue.front();
    queue.pop_front();
    for (uint32_t b : buttons) {
      Player p;
      p.g = n.g;
      int f = p.move(b);
      if (p.g.pub.state == STATE_SUCCESS) return n.frames + f;
      if (p.g.pub.state != STATE_PLAYING) continue;
      std::string key(reinterpret_cast<const char*>(&p.g.tile), sizeof p.g.tile + sizeof p.g.item);
      key += std::to_string(p.g.pub.ball_x * 64 + p.g.pub.ball_y * 4 + p.g.pub.facing);
      if (seen.insert(key).second) queue.push_back({p.g, n.frames + f});
    }
  }
  return -1;
}

TEST(TumbleLevels, EveryLevelCanBeWonInTime) {
  for (int level = 1; level <= tumble_level_count; ++level) {
    int frames = shortest_win_frames(level);
    EXPECT_GT(frames, 0) << "level " << level << " cannot be won";
    EXPECT_LT(frames, tumble_levels[level - 1].time_seconds * 60) << "level " << level;
  }
}

TEST(TumbleLevels, MapsMatchTheTextFiles) {
  for (int level = 1; level <= tumble_level_count; ++level) {
    auto text = tumble_test::read_level(level);
    const LevelDef& def = tumble_levels[level - 1];
    ASSERT_EQ(text.rows.size(), def.height) << "level " << level;
    for (size_t y = 0; y < text.rows.size(); ++y)
      EXPECT_EQ(text.rows[y], std::string(def.cells + y * def.width, def.width)) << "level " << level;
  }
}
