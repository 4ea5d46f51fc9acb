// Game integrations (src/rl/integration.h): every shipped integration loads, and broken ones are
// refused with the manifest's file:line and the field at fault.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.h"
#include "rl/integration.h"

namespace fs = std::filesystem;
using psxrl::rl::Integration;
using psxrl::rl::parse_integration;

namespace {

const std::string kGames = PSXRL_SOURCE_DIR "/games";
const std::string kBuildGames = PSXRL_BUILD_DIR "/games";

// A small valid manifest; each broken case changes one line of it. Line numbers matter.
const char* kManifest =
    "name = \"mini\"\n"                                               // 1
    "[boot]\n"                                                        // 2
    "exe = \"mini.exe\"\n"                                            // 3
    "[variables]\n"                                                   // 4
    "state = { address = 0x80010008, type = \"u32\" }\n"              // 5
    "score = { address = 0x8001000C, type = \"u32\" }\n"              // 6
    "[[actions]]\n"                                                   // 7
    "name = \"FORWARD\"\n"                                            // 8
    "buttons = [\"up\"]\n"                                            // 9
    "[levels]\n"                                                      // 10
    "count = 2\n"                                                     // 11
    "request_variable = \"state\"\n"                                  // 12
    "[moves]\n"                                                       // 13
    "watch = [\"score\"]\n"                                           // 14
    "delay = 4\n"                                                     // 15
    "[episode]\n"                                                     // 16
    "state = \"state\"\n"                                             // 17
    "win = [20]\n";                                                   // 18

std::string replace_line(int line, const std::string& text) {
  std::string m = kManifest;
  size_t start = 0;
  for (int l = 1; l < line; ++l) start = m.find('\n', start) + 1;
  size_t end = m.find('\n', start);
  return m.substr(0, start) + text + m.substr(end);
}

// Parses `text` and returns the error message (empty when it loaded).
std::string error_of(const std::string& text) {
  try {
    parse_integration(text, "mini/game.toml", "mini", kBuildGames);
  } catch (const psx::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Integration, ShippedIntegrationsLoad) {
  auto names = psxrl::rl::list_integrations(kGames);
  ASSERT_EQ(names, (std::vector<std::string>{"kula", "tumble"}));
  Integration t = psxrl::rl::load_integration(kGames, "tumble", kBuildGames);
  EXPECT_EQ(t.actions.size(), 4u);
  EXPECT_EQ(t.actions[3].name, "JUMPFORWARD");
  EXPECT_EQ(t.level_count, 10);
  EXPECT_EQ(t.variable("score").address, 0x8001000Cu);  // games/tumble/README.md: score at 0x0C
  EXPECT_EQ(t.item_rewards.front(), (std::pair<std::int64_t, double>{1000, 0.8}));  // seed Table 3.3
  Integration k = psxrl::rl::load_integration(kGames, "kula", kBuildGames);
  // DESIGN.md's Kula World facts (RAM offsets + 0x80000000).
  EXPECT_EQ(k.variable("time").address, 0x800A2E90u);
  EXPECT_EQ(k.variable("camera").address, 0x800A5498u);
  EXPECT_EQ(k.variable("score").address, 0x800A3E84u);
  EXPECT_EQ(k.variable("state").address, 0x800A2ADCu);
  EXPECT_DOUBLE_EQ(k.variable("time").scale, 1.0 / 50);
  EXPECT_EQ(k.win_states, (std::vector<std::int64_t>{20}));
  EXPECT_TRUE(k.user_disc);
  EXPECT_TRUE(k.needs_bios);
}

TEST(Integration, TheBaseManifestIsValid) { EXPECT_EQ(error_of(kManifest), ""); }

TEST(Integration, UnknownGameListsTheKnownOnes) {
  try {
    psxrl::rl::load_integration(kGames, "pong", kBuildGames);
    FAIL() << "loaded a game that does not exist";
  } catch (const psx::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown game 'pong'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("kula, tumble"), std::string::npos) << e.what();
  }
}

struct BrokenCase {
  int line;
  const char* replacement;
  const char* expected;  // the whole "file:line: field: what" prefix that must appear
};

class BrokenIntegration : public testing::TestWithParam<BrokenCase> {};

TEST_P(BrokenIntegration, IsRefusedWithFileLineAndField) {
  const BrokenCase& c = GetParam();
  std::string message = error_of(replace_line(c.line, c.replacement));
  EXPECT_NE(message.find(c.expected), std::string::npos) << "got: " << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BrokenIntegration,
    testing::Values(
        BrokenCase{5, "state = { address = 0x1F801814, type = \"u32\" }",
                   "mini/game.toml:5: [variables.state] address: expected an aligned address in RAM"},
        BrokenCase{5, "state = { address = 0x80010009, type = \"u32\" }",
                   "mini/game.toml:5: [variables.state] address: expected an aligned address"},
        BrokenCase{5, "state = { address = 0x80010008, type = \"u64\" }",
                   "mini/game.toml:5: [variables.state] type: expected u8, s8, u16, s16, u32 or s32, found 'u64'"},
        BrokenCase{5, "state = { type = \"u32\" }", "mini/game.toml:5: [variables.state] address: missing"},
        BrokenCase{9, "buttons = [\"jump\"]", "mini/game.toml:9: [actions] buttons: unknown button 'jump'"},
        BrokenCase{11, "count = \"two\"", "mini/game.toml:11: [levels] count: expected an integer"},
        BrokenCase{14, "watch = [\"camera\"]", "mini/game.toml:14: [moves] watch: unknown variable 'camera'"},
        BrokenCase{15, "dealy = 4", "mini/game.toml:15: [moves] dealy: unknown field"},
        BrokenCase{15, "delay = 0", "mini/game.toml:15: [moves] delay: expected 1 to 10000, found 0"},
        BrokenCase{17, "state = \"level\"", "mini/game.toml:17: [episode] state: unknown variable 'level'"},
        BrokenCase{18, "win = [20", "mini/game.toml:18:"},  // TOML syntax: an unclosed array
        BrokenCase{16, "[episodes]", "mini/game.toml:16: episodes: unknown field"},
        BrokenCase{12, "request_variable = 12", "mini/game.toml:12: [levels] request_variable: expected a string"},
        BrokenCase{3, "# nothing to boot", "mini/game.toml:2: [boot] exe: expected exactly one of"},
        BrokenCase{1, "name = \"mini\"\nscript_memory_mib = 0",
                   "mini/game.toml:2: script_memory_mib: expected 1 to 4096, found 0"},
        BrokenCase{3, "disc = \"user\"\ndisc_sha1 = [\"ABC\"]",
                   "mini/game.toml:4: [boot] disc_sha1: expected SHA-1s as 40 lower-case hex digits, found 'ABC'"}),
    [](const testing::TestParamInfo<BrokenCase>& info) {
      return "Case" + std::to_string(info.index) + "Line" + std::to_string(info.param.line);
    });

TEST(Integration, MissingTableNamesTheFile) {
  std::string m = kManifest;
  m = m.substr(0, m.find("[episode]"));
  std::string message = error_of(m);
  EXPECT_NE(message.find("mini/game.toml:1: episode: missing table"), std::string::npos) << message;
}

TEST(Integration, ScriptOutsideTheFolderIsRefused) {
  std::string message = error_of("script = \"../other/x.lua\"\n" + std::string(kManifest));
  EXPECT_NE(message.find("mini/game.toml:1: script: expected a file name inside the integration's folder"),
            std::string::npos)
      << message;
}

// #61: a built-in program that is nowhere is reported, when the game boots, at the manifest's
// line with both folders searched (not only the last fallback path).
TEST(Integration, AMissingProgramNamesTheLineAndTheFoldersSearched) {
  Integration g = parse_integration(kManifest, "mini/game.toml", "mini", kBuildGames);
  EXPECT_EQ(g.missing_program, "mini/game.toml:3: [boot] exe: 'mini.exe' is in neither mini/ nor " + kBuildGames +
                                   "/mini/ (is the game built?)");
  Integration t = psxrl::rl::load_integration(kGames, "tumble", kBuildGames);
  EXPECT_EQ(t.missing_program, "");
}

// #61: a game is chosen by its folder, so a manifest naming another game is refused.
TEST(Integration, ANameThatDiffersFromTheFolderIsRefused) {
  fs::path games = fs::temp_directory_path() / "psxrl_misnamed_games";
  fs::remove_all(games);
  fs::create_directories(games / "maxi");
  std::ofstream(games / "maxi" / "game.toml") << kManifest;
  try {
    psxrl::rl::load_integration(games.string(), "maxi", kBuildGames);
    FAIL() << "loaded a manifest named 'mini' from folder 'maxi'";
  } catch (const psx::InputError& e) {
    EXPECT_EQ(std::string(e.what()), (games / "maxi" / "game.toml").string() +
                                         ":1: name: 'mini' differs from the folder's name 'maxi' (a game is chosen "
                                         "by its folder: rename one of them)");
  }
  fs::remove_all(games);
}

TEST(Integration, PathPatternsExpand) {
  Integration g;
  g.folder = "/games/kula";
  psxrl::rl::UserFiles files;
  files.states_dir = "/home/me/kula-states";
  EXPECT_EQ(psxrl::rl::expand("{states}/level{level:02}.state", 7, g, files), "/home/me/kula-states/level07.state");
  EXPECT_EQ(psxrl::rl::expand("levels/level{level:02}.txt", 10, g, files), "/games/kula/levels/level10.txt");
  EXPECT_EQ(psxrl::rl::expand("{level}", 3, g, files), "3");
}

// bios = { path = ... } names a file beside the manifest (or an absolute one); the user then need
// not pass --bios, which still overrides it (Env::boot). Anything else is refused by name.
TEST(Integration, BiosPathIsBesideTheManifest) {
  Integration g = parse_integration(replace_line(3, "exe = \"mini.exe\"\nbios = { path = \"openbios.bin\" }"),
                                    "mini/game.toml", "mini", kBuildGames);
  EXPECT_TRUE(g.needs_bios);
  EXPECT_EQ(g.bios, (fs::path("mini") / "openbios.bin").string());
  EXPECT_TRUE(psxrl::rl::missing_user_files(g, {}, true, true).empty());
  Integration a = parse_integration(replace_line(3, "exe = \"mini.exe\"\nbios = { path = \"/roms/bios.bin\" }"),
                                    "mini/game.toml", "mini", kBuildGames);
  EXPECT_EQ(a.bios, "/roms/bios.bin");
  Integration user = parse_integration(replace_line(3, "exe = \"mini.exe\"\nbios = \"user\""), "mini/game.toml", "mini",
                                       kBuildGames);
  ASSERT_EQ(psxrl::rl::missing_user_files(user, {}, true, true).size(), 1u);
  EXPECT_NE(psxrl::rl::missing_user_files(user, {}, true, true)[0].find("--bios FILE"), std::string::npos);
  EXPECT_NE(error_of(replace_line(3, "exe = \"mini.exe\"\nbios = \"mine.bin\"")).find(
                "mini/game.toml:4: [boot] bios: expected \"none\", \"user\" or { path = \"FILE\" }"),
            std::string::npos);
  EXPECT_NE(error_of(replace_line(3, "exe = \"mini.exe\"\nbios = { file = \"x.bin\" }"))
                .find("mini/game.toml:4: [boot.bios] file: unknown field"),
            std::string::npos);
}

// An unknown game's message says which folder was searched and how to search another.
TEST(Integration, UnknownGameSaysWhereGamesAreLookedFor) {
  try {
    psxrl::rl::load_integration(kGames, "pong", kBuildGames);
    FAIL() << "loaded a game that does not exist";
  } catch (const psx::InputError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("games are looked for in " + kGames), std::string::npos) << m;
    EXPECT_NE(m.find("PSXRL_GAMES"), std::string::npos) << m;
  }
}
