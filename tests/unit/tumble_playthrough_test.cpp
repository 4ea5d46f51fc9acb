// Tumble played on the emulated console through the pad (Console::press/release on port 1):
// scripted playthroughs of levels 1 and 2 to the exit, checking after every move that the RAM
// contract holds what games/tumble/README.md documents; the three ways to lose, each ending in
// its documented state and then game over; the menus by buttons; rumble on a DualShock. Expected
// positions and scores come from walking the route over the level's text map in the test itself
// (tumble_test_util.h reads games/tumble/levels/ directly), not from the game.
#include <gtest/gtest.h>

#include <string>

#include "tumble_console_util.h"
#include "tumble_test_util.h"

using tumble_test::Boot;
using tumble_test::read_level;
using tumble_test::route_buttons;
using tumble_test::TumbleConsole;

namespace {

// Level routes, the same as the rule tests' (tumble_rules_test.cpp explains them).
const char* kLevel1Route = "LF" "RFFFFF" "RFF" "RFFFFF" "LF" "LFFFFF" "LFFFF";
const char* kLevel2Route = "LLFF" "F" "RFFFFF" "RFFFFFF" "RFFFFF" "RFFFFFF";

// The test's own model of a level in play: position, facing, score and keys from the text map and
// the README's rules (F rolls one tile along the facing, L/R turn 90 degrees, items are collected
// by landing on them: coin 250, fruit 500, key 1000).
struct RouteModel {
  tumble_test::LevelText map;
  int x = 0, y = 0, facing = 0;
  psx::u32 score = 0, keys = 0;
  RouteModel(int level, int facing0) : map(read_level(level)), facing(facing0) {
    for (int r = 0; r < static_cast<int>(map.rows.size()); ++r)
      for (int c = 0; c < static_cast<int>(map.rows[r].size()); ++c)
        if (map.rows[r][c] == 'S') x = c, y = r;
  }
  // Applies one route letter; returns the frames the README says the move lasts.
  psx::u32 apply(char move) {
    static const int dx[4] = {0, 1, 0, -1}, dy[4] = {-1, 0, 1, 0};
    if (move == 'L') facing = (facing + 3) % 4;
    if (move == 'R') facing = (facing + 1) % 4;
    if (move == 'L' || move == 'R') return 12;
    x += dx[facing], y += dy[facing];
    char& cell = map.rows[y][x];
    psx::u32 extra = 0;
    if (cell == 'c') score += 250, extra = 250 / 50 + 2;
    if (cell == 'f') score += 500, extra = 500 / 50 + 2;
    if (cell == 'k') score += 1000, extra = 1000 / 50 + 2, ++keys;
    if (cell == 'c' || cell == 'f' || cell == 'k') cell = '#';
    return 16 + extra;
  }
};

// Plays `route` on `level` by the pad, checking the contract after every move against the model.
void play_route(TumbleConsole& t, int level, int facing0, const std::string& route, psx::u32 time_s) {
  RouteModel model(level, facing0);
  // The level began state_timer frames ago (README: frames spent in the current state).
  psx::u32 start_frame = t.word(TUMBLE_FIELD(frame)) - t.word(TUMBLE_FIELD(state_timer));
  for (size_t i = 0; i < route.size(); ++i) {
    SCOPED_TRACE("level " + std::to_string(level) + " move " + std::to_string(i) + " '" + route[i] + "'");
    ASSERT_EQ(t.state(), STATE_PLAYING);
    psx::u32 expected_frames = model.apply(route[i]);
    t.console.press(1, route_buttons(route[i]));
    for (int f = 0; f < 10 && t.word(TUMBLE_FIELD(move)) == MOVE_NONE; ++f) t.console.run_frame();
    t.console.release(1, route_buttons(route[i]));
    psx::u32 taken = t.word(TUMBLE_FIELD(frame));  // the game frame that took the move
    EXPECT_EQ(t.word(TUMBLE_FIELD(move)), route[i] == 'F' ? 1u : route[i] == 'R' ? 2u : 3u);
    EXPECT_EQ(t.word(TUMBLE_FIELD(move_length)), expected_frames);
    // A move lasts at most a few dozen frames; 1000 console frames means it never ended.
    for (int f = 0; f < 1000 && t.word(TUMBLE_FIELD(move)) != MOVE_NONE && t.state() == STATE_PLAYING; ++f)
      t.console.run_frame();
    ASSERT_FALSE(t.word(TUMBLE_FIELD(move)) != MOVE_NONE && t.state() == STATE_PLAYING)
        << "the move did not end within 1000 frames";
    bool last = i + 1 == route.size();
    EXPECT_EQ(t.state(), last ? STATE_SUCCESS : STATE_PLAYING);
    if (!last) {
      EXPECT_EQ(t.word(TUMBLE_FIELD(frame)) - taken, expected_frames);
    }
    EXPECT_EQ(t.word(TUMBLE_FIELD(ball_x)), static_cast<psx::u32>(model.x));
    EXPECT_EQ(t.word(TUMBLE_FIELD(ball_y)), static_cast<psx::u32>(model.y));
    EXPECT_EQ(t.word(TUMBLE_FIELD(facing)), static_cast<psx::u32>(model.facing));
    EXPECT_EQ(t.word(TUMBLE_FIELD(camera_angle)), static_cast<psx::u32>(model.facing) * 1024);
    EXPECT_EQ(t.word(TUMBLE_FIELD(score)), model.score);  // the count-up is over when the move ends
    EXPECT_EQ(t.word(TUMBLE_FIELD(score_target)), model.score);
    EXPECT_EQ(t.word(TUMBLE_FIELD(keys_held)), model.keys);
    EXPECT_EQ(t.word(TUMBLE_FIELD(move_frame)), 0u);
    EXPECT_EQ(t.word(TUMBLE_FIELD(level)), static_cast<psx::u32>(level));
    if (!last) {  // the clock loses one tick per game frame in play
      EXPECT_EQ(t.word(TUMBLE_FIELD(clock)), time_s * 60 - (t.word(TUMBLE_FIELD(frame)) - start_frame));
    }
  }
  EXPECT_EQ(model.score, static_cast<psx::u32>(model.map.max_score()));
}

}  // namespace

TEST(TumblePlaythrough, Levels1And2ByThePadReachTheExitWithFullScores) {
  TumbleConsole t;
  ASSERT_TRUE(t.start_level(1));
  EXPECT_EQ(t.word(TUMBLE_FIELD(map_width)), read_level(1).rows[0].size());
  EXPECT_EQ(t.word(TUMBLE_FIELD(map_height)), read_level(1).rows.size());
  EXPECT_EQ(t.word(TUMBLE_FIELD(keys_needed)), 1u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(clock)), 60u * 60u);  // level01.txt "time: 60"
  t.run_game_frames(20);
  t.screenshot("level1");
  play_route(t, 1, 0, kLevel1Route, 60);
  EXPECT_EQ(t.state(), STATE_SUCCESS);
  EXPECT_EQ(t.word(TUMBLE_FIELD(score)), 4000u);  // 8 coins, 2 fruit, 1 key
  EXPECT_EQ(t.word(TUMBLE_FIELD(levels_completed)), 1u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(ball_x)), 0u);  // the exit, E at the top left of level01.txt
  EXPECT_EQ(t.word(TUMBLE_FIELD(ball_y)), 0u);
  EXPECT_TRUE(t.run_game_frames(40));
  t.screenshot("level_complete");
  // Level complete lasts 150 frames, then level 2 starts by itself with its own map and clock.
  EXPECT_TRUE(t.run_game_frames(150 - 40));
  ASSERT_EQ(t.state(), STATE_PLAYING);
  EXPECT_EQ(t.word(TUMBLE_FIELD(level)), 2u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(score)), 0u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(keys_needed)), 2u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(facing)), 1u);  // level02.txt "facing: E"
  play_route(t, 2, 1, kLevel2Route, 90);
  EXPECT_EQ(t.state(), STATE_SUCCESS);
  EXPECT_EQ(t.word(TUMBLE_FIELD(score)), 9u * 250 + 2 * 500 + 2 * 1000);
  EXPECT_EQ(t.word(TUMBLE_FIELD(levels_completed)), 2u);
}

TEST(TumblePlaythrough, RollingOffThePlatformFallsThenGameOverThenTitle) {
  // Level 2 starts at (3,5) facing east; north of it, (3,4), is a hole.
  TumbleConsole t;
  ASSERT_TRUE(t.start_level(2));
  t.move(route_buttons('L'));
  t.move(route_buttons('F'));
  EXPECT_EQ(t.state(), STATE_FALLEN);  // 6
  EXPECT_EQ(t.word(TUMBLE_FIELD(ball_x)), 3u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(ball_y)), 4u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(move)), 0u);
  t.run_game_frames(30);
  t.screenshot("fallen");
  // A lost state lasts 120 frames, then game over (18); Start (after 30 frames) goes to the title.
  psx::u32 lost_at = t.word(TUMBLE_FIELD(frame)) - t.word(TUMBLE_FIELD(state_timer));
  // Bounded at 200 game frames: the expected 120 and some.
  for (int f = 0; f < 200 && t.state() == STATE_FALLEN && t.run_game_frames(1); ++f) {
  }
  EXPECT_EQ(t.state(), STATE_GAME_OVER) << "still fallen (6) after 200 game frames, or the console stopped";
  EXPECT_EQ(t.word(TUMBLE_FIELD(frame)) - lost_at, 120u);
  t.run_game_frames(40);
  t.screenshot("game_over");
  t.tap(psx::pad_button::kStart);
  EXPECT_EQ(t.state(), STATE_TITLE);
}

TEST(TumblePlaythrough, RollingOntoSpikesKills) {
  // Level 4 starts at (0,2) facing east; the spikes are at (4,2).
  TumbleConsole t;
  ASSERT_TRUE(t.start_level(4));
  for (int i = 0; i < 3; ++i) t.move(route_buttons('F'));
  ASSERT_EQ(t.state(), STATE_PLAYING);
  t.move(route_buttons('F'));
  EXPECT_EQ(t.state(), STATE_SPIKED);  // 2
  EXPECT_EQ(t.word(TUMBLE_FIELD(ball_x)), 4u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(ball_y)), 2u);
  EXPECT_TRUE(t.word(TUMBLE_FIELD(events)) & TUMBLE_EV_SPIKED);
  t.run_game_frames(10);
  t.screenshot("spiked");
  t.run_game_frames(120);
  EXPECT_EQ(t.state(), STATE_GAME_OVER);
}

TEST(TumblePlaythrough, ClockRunningOutIsTimeUp) {
  // The clock is a writable contract field; 90 frames left instead of level 1's 3600 keeps this
  // test short. It ticks once per game frame in play and reaching 0 is time up (state 4).
  TumbleConsole t;
  ASSERT_TRUE(t.start_level(1));
  t.set_word(TUMBLE_FIELD(clock), 90);
  ASSERT_TRUE(t.run_game_frames(89));
  EXPECT_EQ(t.state(), STATE_PLAYING);
  EXPECT_EQ(t.word(TUMBLE_FIELD(clock)), 1u);
  ASSERT_TRUE(t.run_game_frames(1));
  EXPECT_EQ(t.state(), STATE_TIME_UP);
  EXPECT_EQ(t.word(TUMBLE_FIELD(clock)), 0u);
  EXPECT_TRUE(t.word(TUMBLE_FIELD(events)) & TUMBLE_EV_TIME_UP);
  t.run_game_frames(120);
  EXPECT_EQ(t.state(), STATE_GAME_OVER);
}

TEST(TumblePlaythrough, MenusByThePadStartLevel5) {
  TumbleConsole t;
  for (int i = 0; i < 600 && t.word(TUMBLE_FIELD(magic)) != TUMBLE_MAGIC; ++i) t.console.run_frame();
  ASSERT_TRUE(t.run_game_frames(60));
  EXPECT_EQ(t.state(), STATE_TITLE);  // 50
  t.screenshot("title");
  t.tap(psx::pad_button::kStart);
  EXPECT_EQ(t.state(), STATE_LEVEL_SELECT);  // 56
  EXPECT_EQ(t.word(TUMBLE_FIELD(menu_level)), 1u);
  for (int i = 0; i < 4; ++i) t.tap(psx::pad_button::kRight);
  EXPECT_EQ(t.word(TUMBLE_FIELD(menu_level)), 5u);
  t.tap(psx::pad_button::kLeft);
  t.tap(psx::pad_button::kRight);
  EXPECT_EQ(t.word(TUMBLE_FIELD(menu_level)), 5u);
  t.run_game_frames(10);
  t.screenshot("level_select");
  t.tap(psx::pad_button::kCross);
  EXPECT_EQ(t.state(), STATE_PLAYING);
  EXPECT_EQ(t.word(TUMBLE_FIELD(level)), 5u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(clock)) + t.word(TUMBLE_FIELD(state_timer)), 80u * 60u);  // "time: 80"
  t.run_game_frames(100);
  t.screenshot("level5");
}

TEST(TumblePlaythrough, LookTurnsTheCameraOverTwelveFrames) {
  // README: a LOOK lasts 12 frames and camera_angle turns 1024/12 per frame.
  TumbleConsole t;
  ASSERT_TRUE(t.start_level(1));
  t.console.press(1, route_buttons('R'));
  for (int f = 0; f < 10 && t.word(TUMBLE_FIELD(move)) == MOVE_NONE; ++f) t.console.run_frame();
  t.console.release(1, route_buttons('R'));
  ASSERT_EQ(t.word(TUMBLE_FIELD(move)), static_cast<psx::u32>(MOVE_LOOK_RIGHT));
  ASSERT_TRUE(t.run_game_frames(6));
  EXPECT_EQ(t.word(TUMBLE_FIELD(move_frame)), 6u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(camera_angle)), 6u * 1024 / 12);
  ASSERT_TRUE(t.run_game_frames(6));
  EXPECT_EQ(t.word(TUMBLE_FIELD(camera_angle)), 1024u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(facing)), 1u);
}

TEST(TumblePlaythrough, CrumblingTileRumblesADualShock) {
  // Level 5 starts at (3,5) facing north on floor; (3,4) and (3,3) crumble. Leaving (3,4) starts it
  // crumbling, which the game announces with the large motor.
  TumbleConsole t(Boot::Exe, nullptr, /*dualshock=*/true);
  ASSERT_TRUE(t.start_level(5));
  t.move(route_buttons('F'));
  EXPECT_EQ(t.console.rumble(1).large, 0);
  t.console.press(1, route_buttons('F'));
  bool rumbled = false;
  for (int f = 0; f < 8; ++f) {
    t.console.run_frame();
    rumbled = rumbled || t.console.rumble(1).large > 0;
  }
  t.console.release(1, route_buttons('F'));
  EXPECT_TRUE(rumbled);
  t.run_game_frames(40);
  EXPECT_EQ(t.console.rumble(1).large, 0);  // the warning lasts 20 frames
}
