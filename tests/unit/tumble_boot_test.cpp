// Tumble from its disc image (build/games/tumble/tumble.cue, made by tools/mkdisc) and from the
// EXE: the same pad input gives the same game, byte for byte; the README's demo script
// (games/tumble/demo/level1.txt, read by the CLI's own --input parser) plays level 1 from the
// title to the exit with the full score; the game makes sound when things happen.
#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

#include "cli/input_script.h"
#include "core/hash.h"
#include "tumble_console_util.h"

using tumble_test::Boot;
using tumble_test::route_buttons;
using tumble_test::TumbleConsole;

namespace {

psx::u64 hash(std::span<const psx::u8> bytes) { return psx::fnv1a(bytes.data(), bytes.size()); }

// Boots, runs to game frame 40 on the title, starts level 1 through the request variable and
// plays a few moves by the pad.
void play_a_little(TumbleConsole& t) {
  for (int i = 0; i < 600 && t.word(TUMBLE_FIELD(magic)) != TUMBLE_MAGIC; ++i) t.console.run_frame();
  ASSERT_TRUE(t.run_game_frames(40 - t.word(TUMBLE_FIELD(frame))));
  ASSERT_EQ(t.word(TUMBLE_FIELD(frame)), 40u);
  t.set_word(TUMBLE_FIELD(request_level), 1);
  ASSERT_TRUE(t.run_game_frames(1));
  for (char m : std::string("LFRFF")) t.move(route_buttons(m));
  ASSERT_EQ(t.state(), STATE_PLAYING);
  EXPECT_EQ(t.word(TUMBLE_FIELD(score)), 750u);  // three coins on the way: (1,5), (1,4), (1,3)
}

}  // namespace

TEST(TumbleBoot, ExeAndDiscGiveIdenticalRam) {
  TumbleConsole exe(Boot::Exe), disc(Boot::Disc);
  play_a_little(exe);
  play_a_little(disc);
  EXPECT_EQ(exe.word(TUMBLE_FIELD(frame)), disc.word(TUMBLE_FIELD(frame)));
  // User RAM from the program's load address (the contract, 0x80010000) to the top of RAM: code,
  // data, the game state, ordering tables, primitive buffers and the stack.
  auto user = [](TumbleConsole& t) { return t.console.ram().subspan(0x10000); };
  EXPECT_EQ(hash(user(exe)), hash(user(disc)));
}

TEST(TumbleBoot, DiscThroughTheProjectBootRomGivesIdenticalRam) {
  // No HLE at all: the project's disc boot ROM reads SYSTEM.CNF and TUMBLE.EXE through the
  // emulated CD-ROM drive, as a BIOS would.
  TumbleConsole exe(Boot::Exe), rom(Boot::Disc, PSXRL_BUILD_DIR "/tests/roms/cdboot_rom.bin");
  play_a_little(exe);
  play_a_little(rom);
  // Everything from the load address up to the stack's last 4 KiB: the ROM's own last calls run
  // on the game's stack (SP is set before the jump) and leave words below the game's deepest
  // frame that the game never reads, as a BIOS's Exec() does too.
  auto user = [](TumbleConsole& t) { return t.console.ram().subspan(0x10000, 0x1FF000 - 0x10000); };
  EXPECT_EQ(hash(user(exe)), hash(user(rom)));
}

TEST(TumbleBoot, DemoScriptPlaysLevel1FromTheTitleToTheExit) {
  // The README's main command runs this script with `psxrl run --input`; the same presses here.
  std::vector<psxrl::cli::InputPress> presses =
      psxrl::cli::read_input_script(std::string(TUMBLE_DEMO_DIR) + "/level1.txt");
  ASSERT_FALSE(presses.empty());
  TumbleConsole t;
  size_t next = 0;
  for (psx::u64 f = 0; f <= presses.back().frame + 60; ++f) {
    for (; next < presses.size() && presses[next].frame == f; ++next)
      t.console.press_for(1, presses[next].buttons, presses[next].hold);
    t.console.run_frame();
  }
  EXPECT_EQ(t.state(), STATE_SUCCESS);
  EXPECT_EQ(t.word(TUMBLE_FIELD(level)), 1u);
  EXPECT_EQ(t.word(TUMBLE_FIELD(score)), 4000u);  // level 1's maximum: 8 coins, 2 fruit, 1 key
  EXPECT_EQ(t.word(TUMBLE_FIELD(levels_completed)), 1u);
}

TEST(TumbleBoot, EventsMakeSound) {
  // Silence while the ball rests (no effect plays), sound once it turns (the look effect).
  TumbleConsole t;
  ASSERT_TRUE(t.start_level(1));
  std::vector<psx::StereoSample> audio;
  t.console.take_audio(audio);
  audio.clear();
  t.run_game_frames(10);
  t.console.take_audio(audio);
  auto loud = [](const std::vector<psx::StereoSample>& a) {
    int peak = 0;
    for (const psx::StereoSample& s : a) peak = std::max({peak, std::abs(int{s.left}), std::abs(int{s.right})});
    return peak;
  };
  EXPECT_EQ(loud(audio), 0);
  t.console.press(1, route_buttons('L'));
  t.run_game_frames(2);
  t.console.release(1, route_buttons('L'));
  audio.clear();
  t.run_game_frames(10);
  t.console.take_audio(audio);
  EXPECT_GT(audio.size(), 10u * 700);  // 44100 / 60 = 735 samples a frame
  EXPECT_GT(loud(audio), 1000);
}
