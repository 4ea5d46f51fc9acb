// Tumble on the emulated console: the PlayStation program boots (without a BIOS), publishes its
// RAM contract at 0x80010000 as games/tumble/README.md documents it, and starts a level when the
// request variable is written. Button-driven playthroughs join these once the pads are emulated.
#include <gtest/gtest.h>

#include <cstddef>

#include "contract.h"
#include "core/console.h"
#include "game.h"

namespace {

constexpr psx::u32 kContract = 0x80010000;

// Offsets documented in README.md; a change to the struct must change the README too.
static_assert(offsetof(TumbleContract, state) == 0x08);
static_assert(offsetof(TumbleContract, score) == 0x0C);
static_assert(offsetof(TumbleContract, clock) == 0x14);
static_assert(offsetof(TumbleContract, camera_angle) == 0x18);
static_assert(offsetof(TumbleContract, ball_x) == 0x1C);
static_assert(offsetof(TumbleContract, facing) == 0x24);
static_assert(offsetof(TumbleContract, level) == 0x28);
static_assert(offsetof(TumbleContract, levels_completed) == 0x34);
static_assert(offsetof(TumbleContract, move) == 0x38);
static_assert(offsetof(TumbleContract, rng) == 0x44);
static_assert(offsetof(TumbleContract, request_level) == 0x48);
static_assert(offsetof(TumbleContract, state_timer) == 0x64);
static_assert(offsetof(TumbleContract, camera_z) == 0x70);

struct TumbleConsole {
  psx::Console console;
  explicit TumbleConsole(const char* bios = nullptr) {
    if (bios) console.load_bios(bios);
    console.boot_exe(TUMBLE_EXE);
  }
  psx::u32 word(psx::u32 offset) { return console.read32(kContract + offset); }
  void set_word(psx::u32 offset, psx::u32 v) { console.write32(kContract + offset, v); }
  // Runs emulated frames until the game has run `n` more frames of its own (bounded).
  bool run_game_frames(psx::u32 n) {
    psx::u32 target = word(offsetof(TumbleContract, frame)) + n;
    for (int i = 0; i < 3000 && word(offsetof(TumbleContract, frame)) < target; ++i) console.run_frame();
    return word(offsetof(TumbleContract, frame)) >= target && !console.stopped();
  }
};

}  // namespace

TEST(TumbleConsole, BootsToTitleWithContract) {
  TumbleConsole t;
  ASSERT_TRUE(t.run_game_frames(3));
  EXPECT_EQ(t.word(offsetof(TumbleContract, magic)), 0x4C424D54u);  // "TMBL"
  EXPECT_EQ(t.word(offsetof(TumbleContract, version)), 2u);
  EXPECT_EQ(t.word(offsetof(TumbleContract, state)), 50u);  // title
  EXPECT_EQ(t.word(offsetof(TumbleContract, level_count)), 10u);
  EXPECT_EQ(t.word(offsetof(TumbleContract, level)), 0u);
}

TEST(TumbleConsole, RequestVariableStartsLevelAndClockCountsDown) {
  TumbleConsole t;
  ASSERT_TRUE(t.run_game_frames(2));
  t.set_word(offsetof(TumbleContract, request_level), 1);
  ASSERT_TRUE(t.run_game_frames(1));
  EXPECT_EQ(t.word(offsetof(TumbleContract, request_level)), 0u);
  EXPECT_EQ(t.word(offsetof(TumbleContract, state)), 48u);  // playing
  EXPECT_EQ(t.word(offsetof(TumbleContract, level)), 1u);
  // Level 1 (levels/level01.txt): 5x6 map, start (2,5) facing north, one key, 60 s.
  EXPECT_EQ(t.word(offsetof(TumbleContract, map_width)), 5u);
  EXPECT_EQ(t.word(offsetof(TumbleContract, map_height)), 6u);
  EXPECT_EQ(t.word(offsetof(TumbleContract, ball_x)), 2u);
  EXPECT_EQ(t.word(offsetof(TumbleContract, ball_y)), 5u);
  EXPECT_EQ(t.word(offsetof(TumbleContract, facing)), 0u);
  EXPECT_EQ(t.word(offsetof(TumbleContract, keys_needed)), 1u);
  psx::u32 frame0 = t.word(offsetof(TumbleContract, frame));
  psx::u32 clock0 = t.word(offsetof(TumbleContract, clock));
  EXPECT_LE(clock0, 3600u);
  ASSERT_TRUE(t.run_game_frames(30));
  psx::u32 elapsed = t.word(offsetof(TumbleContract, frame)) - frame0;
  EXPECT_EQ(t.word(offsetof(TumbleContract, clock)), clock0 - elapsed);  // one tick per game frame
  EXPECT_EQ(t.word(offsetof(TumbleContract, score)), 0u);
}

#ifdef TUMBLE_BOOTROM
// With the project's boot ROM instead of the HLE kernel the game must behave the same: it uses no
// BIOS service, so the level it starts and the clock it keeps do not depend on what booted it.
TEST(TumbleConsole, SameGameUnderTheBootRom) {
  TumbleConsole hle, rom(TUMBLE_BOOTROM);
  for (TumbleConsole* t : {&hle, &rom}) {
    ASSERT_TRUE(t->run_game_frames(2));
    EXPECT_EQ(t->word(offsetof(TumbleContract, state)), 50u);
    t->set_word(offsetof(TumbleContract, request_level), 3);
    ASSERT_TRUE(t->run_game_frames(20));
  }
  for (psx::u32 field : {offsetof(TumbleContract, state), offsetof(TumbleContract, level),
                         offsetof(TumbleContract, ball_x), offsetof(TumbleContract, ball_y),
                         offsetof(TumbleContract, facing), offsetof(TumbleContract, keys_needed),
                         offsetof(TumbleContract, rng)})
    EXPECT_EQ(hle.word(field), rom.word(field)) << "contract offset " << field;
  // The clock ticks once per frame in play: clock + state_timer is level 3's 60 s in frames.
  for (TumbleConsole* t : {&hle, &rom})
    EXPECT_EQ(t->word(offsetof(TumbleContract, clock)) + t->word(offsetof(TumbleContract, state_timer)), 3600u);
  EXPECT_EQ(rom.word(offsetof(TumbleContract, level)), 3u);
  EXPECT_EQ(rom.word(offsetof(TumbleContract, ball_y)), 8u);  // level 3 starts at (2,8)
}
#endif
