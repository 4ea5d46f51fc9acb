// games/kula without Kula World: the integration runs, the user's way (a disc, a BIOS, level-start
// save states and level maps), against a synthetic RAM trace program (tests/roms/kula_trace.c) on
// a disc booted by the project's cdboot ROM. The trace writes Kula's variables at Kula's addresses
// with documented timings, so move boundaries, rewards, the tracked position and terminal states
// follow by arithmetic. Also: the messages when the user's files are missing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/console.h"
#include "core/input_error.h"
#include "core/sha1.h"
#include "rl/env.h"

namespace fs = std::filesystem;
using psxrl::rl::Env;
using psxrl::rl::EnvConfig;

namespace {

const std::string kBuild = PSXRL_BUILD_DIR;
constexpr psx::u32 kState = 0x800A2ADC;
constexpr double kGamma = 0.9;

// What a user does once per level with `psxrl play`: boot the game and save a state when the
// level has started (state 48).
std::string make_level_state() {
  fs::path dir = fs::temp_directory_path() / "psxrl_kula_states";
  fs::create_directories(dir);
  psx::Console c;
  c.load_bios(kBuild + "/tests/roms/cdboot_rom.bin");
  c.insert_disc(kBuild + "/tests/roms/kula_trace.cue");
  c.boot_disc();
  EXPECT_TRUE(c.run_until([&] { return c.read32(kState) == 48; }, 600)) << c.fatal_error();
  c.save_state_file((dir / "level01.state").string());
  return dir.string();
}

EnvConfig kula(const std::string& obs) {
  EnvConfig cfg;
  cfg.game = "kula";
  cfg.obs = obs;
  cfg.gamma = kGamma;
  cfg.files.disc = kBuild + "/tests/roms/kula_trace.cue";
  cfg.files.bios = kBuild + "/tests/roms/cdboot_rom.bin";
  cfg.files.maps_dir = PSXRL_SOURCE_DIR "/tests/data/kula_trace";
  cfg.files.states_dir = make_level_state();
  return cfg;
}

std::string construct_error(const EnvConfig& cfg) {
  try {
    Env env(cfg);
    env.reset(1, 0, nullptr);
  } catch (const psx::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// The trace level (tests/data/kula_trace/level01.txt): a column x=1 from S (1,4) north over a key
// (1,3), fruit (1,2) and coin (1,1) to the exit (1,0). A move's camera changes on its frames 1..N
// (FORWARD N=20, LOOK 15, JUMPFORWARD 40), the count-up adds 50 a frame afterwards (key 20
// frames, fruit 10, coin 5), and the delimiter (initial delay 12, delay 4) ends the move 4
// frames after the last change. So FORWARD onto the key lasts 20 + 20 + 4 = 44 frames.
TEST(EnvKula, TraceMovesRewardsPositionAndWin) {
  Env env(kula("simple"));
  psxrl::rl::StepInfo info;
  env.reset(1, 0, &info);
  EXPECT_EQ(info.state, 48);
  // The trace starts the clock at 60 s (3000 fiftieths) and ticks it in the frame the level starts,
  // the frame the state was saved in.
  EXPECT_NEAR(info.time_left, 2999 * 0.02, 1e-9);
  auto simple = [&] { return *static_cast<const std::int64_t*>(env.observation()[0].data); };
  EXPECT_EQ(simple(), 4 * 3 * 4 + 4 * 1 + 0);  // (1, 4) facing north, w = 3

  struct Expect {
    int action;
    std::uint64_t frames;
    double units;  // reward in units of (1 - gamma)
    int x, y, facing;
  } moves[] = {
      {1, 15 + 4, 0.0, 1, 4, 1},       // LOOKRIGHT: face east
      {2, 15 + 4, 0.0, 1, 4, 0},       // LOOKLEFT: north again
      {0, 20 + 20 + 4, 0.8, 1, 3, 0},  // FORWARD onto the key: +1000
      {0, 20 + 10 + 4, 0.7, 1, 2, 0},  // the fruit: +500
      {0, 20 + 5 + 4, 0.5, 1, 1, 0},   // the coin: +250
  };
  for (const auto& m : moves) {
    SCOPED_TRACE("action " + std::to_string(m.action));
    auto r = env.step(m.action);
    EXPECT_EQ(r.info.game_frames, m.frames);
    EXPECT_NEAR(r.reward, m.units * (1 - kGamma), 1e-12);
    EXPECT_FALSE(r.terminated);
    EXPECT_EQ(simple(), 4 * 3 * m.y + 4 * m.x + m.facing);
  }
  auto last = env.step(0);  // (1,1) -> (1,0), the exit: the win ends the move on landing
  EXPECT_TRUE(last.terminated);
  EXPECT_EQ(last.info.outcome, "win");
  EXPECT_EQ(last.info.game_frames, 20u);
  EXPECT_EQ(last.info.score, 1000 + 500 + 250);
}

TEST(EnvKula, ReachingTheExitWinsAndFallingLoses) {
  Env env(kula("local"));
  env.reset(1, 0, nullptr);
  // JUMPFORWARD from (1,4) lands on (1,2), the fruit: 40 frames, then 10 of count-up, + 4.
  auto r = env.step(3);
  EXPECT_EQ(r.info.game_frames, 40u + 10 + 4);
  EXPECT_NEAR(r.reward, 0.7 * (1 - kGamma), 1e-12);
  r = env.step(3);  // over the coin (not collected) onto the exit: the win ends the move at once
  EXPECT_TRUE(r.terminated);
  EXPECT_EQ(r.info.outcome, "win");
  EXPECT_EQ(r.info.game_frames, 40u);
  EXPECT_NEAR(r.reward, 1.0 * (1 - kGamma), 1e-12);

  env.reset(1, 0, nullptr);
  env.step(1);       // face east
  r = env.step(0);   // (2,4) is floor
  EXPECT_FALSE(r.terminated);
  r = env.step(0);   // (3,4) is off the map: state 6 on landing, frame 20
  EXPECT_TRUE(r.terminated);
  EXPECT_EQ(r.info.outcome, "lose");
  EXPECT_EQ(r.info.state, 6);
  EXPECT_EQ(r.info.game_frames, 20u);
  EXPECT_NEAR(r.reward, -(1 - kGamma), 1e-12);
}

// Kula World with nothing supplied: one message names all four missing things (issue #62) and
// points at the integration's README; supplying some leaves the others named.
TEST(EnvKula, MissingUserFilesAreNamedInOneMessage) {
  EnvConfig cfg;
  cfg.game = "kula";
  std::string all = construct_error(cfg);
  for (const char* what : {"(see " PSXRL_SOURCE_DIR "/games/kula/README.md)", "BIOS image: pass --bios FILE",
                           "disc image: pass --disc FILE.cue", "save states: pass --states DIR",
                           "level maps, for this observation: pass --maps DIR"})
    EXPECT_NE(all.find(what), std::string::npos) << what << " not in: " << all;
  cfg.files.bios = kBuild + "/tests/roms/cdboot_rom.bin";
  cfg.files.disc = kBuild + "/tests/roms/kula_trace.cue";
  std::string two = construct_error(cfg);
  EXPECT_EQ(two.find("--bios"), std::string::npos) << two;
  EXPECT_EQ(two.find("--disc"), std::string::npos) << two;
  EXPECT_NE(two.find("--states DIR"), std::string::npos) << two;
  EXPECT_NE(two.find("--maps DIR"), std::string::npos) << two;
  cfg.files.maps_dir = "/nonexistent-maps";
  cfg.files.states_dir = "/nonexistent-states";
  EXPECT_NE(construct_error(cfg).find("/nonexistent-states/level01.state: cannot open file"), std::string::npos);
}

// An integration that pins its disc by the SHA-1 of the data track accepts that disc and refuses
// another, naming both hashes. mkdisc writes the trace disc as one data track, so the track's
// sectors are the whole .bin file.
TEST(EnvKula, DiscIdentityBySha1OfTheDataTrack) {
  auto bin = psx::read_file(kBuild + "/tests/roms/kula_trace.bin");
  psx::Sha1 sha;
  sha.update(bin.data(), bin.size());
  std::string right = sha.hex();
  auto manifest_bytes = psx::read_file(PSXRL_SOURCE_DIR "/games/kula/game.toml");
  std::string manifest(manifest_bytes.begin(), manifest_bytes.end());
  auto write = [&](const std::string& sha1) {
    fs::path games = fs::temp_directory_path() / "psxrl_kula_sha1";
    fs::create_directories(games / "kula");
    std::string m = manifest;
    m.replace(m.find("disc_sha1 = []"), 14, "disc_sha1 = [\"" + sha1 + "\"]");
    std::ofstream(games / "kula" / "game.toml") << m;
    fs::copy_file(PSXRL_SOURCE_DIR "/games/kula/game.lua", games / "kula" / "game.lua", fs::copy_options::overwrite_existing);
    return games.string();
  };
  EnvConfig cfg = kula("episode");
  cfg.games_dir = write(right);
  Env ok(cfg);
  EXPECT_EQ(ok.reset(1, 0, nullptr).size(), 1u);
  cfg.games_dir = write(std::string(40, '0'));
  std::string message = construct_error(cfg);
  EXPECT_NE(message.find("its data track's SHA-1 is " + right + ", expected one of " + std::string(40, '0')),
            std::string::npos)
      << message;
}

// FIPS 180 example messages and their published digests.
TEST(Sha1, KnownAnswers) {
  auto hex = [](const std::string& s) {
    psx::Sha1 h;
    h.update(s.data(), s.size());
    return h.hex();
  };
  EXPECT_EQ(hex(""), "da39a3ee5e6b4b0d3255bfef95601890afd80709");
  EXPECT_EQ(hex("abc"), "a9993e364706816aba3e25717850c26c9cd0d89d");
  EXPECT_EQ(hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"), "84983e441c3bd26ebaae4aa1f95129e5e54670f1");
  EXPECT_EQ(hex(std::string(1000000, 'a')), "34aa973cd4c4daa4f61eeb2bdbad27316534016f");
}
