// Training from saved states (--start-states, the seed's §5 "resume play from a previous state"):
// an environment started from a snapshot shows the snapshot's picture, not the level start's, and
// plays on exactly as the original episode did; a trainer with --start-states 1 starts every
// training episode but the first (never a test) from a saved state, the same way on every run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "rl/agents/trainer.h"

using namespace psxrl::agents;
namespace rl = psxrl::rl;

namespace {

std::string run_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("psxrl_agent_starts_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir.string();
}

TrainConfig tiny(const std::string& out, double start_states) {
  TrainConfig c;
  c.agent = "q";
  c.env.obs = "simple";
  c.env.max_moves = 4;
  c.episodes = 6;
  c.test_every = 3;
  c.seed = 8;
  c.start_states = start_states;
  c.out = out;
  return c;
}

std::vector<std::string> rows(const std::vector<EpisodeRecord>& records) {
  std::vector<std::string> out;
  for (const EpisodeRecord& r : records)
    out.push_back(std::to_string(r.episode) + " " + std::to_string(r.saved_start) + " " + std::to_string(r.score) +
                  " " + std::to_string(r.moves) + " " + std::to_string(r.frames) + " " + r.outcome + " " +
                  std::to_string(r.total_moves));
  return out;
}

// Tumble's actions: 0 FORWARD, 1 LOOKRIGHT, 2 LOOKLEFT, 3 JUMPFORWARD.
constexpr int kLookRight = 1;

}  // namespace

TEST(StartStates, SnapshotStartsWhereTheEpisodeWasAndPlaysOnTheSame) {
  rl::EnvConfig config;
  config.obs = "visual";
  rl::Env env(config);
  std::vector<float> start = features(env.reset(1, 5));
  env.step(kLookRight);  // the camera turns: another picture, on the same square
  std::vector<float> turned = features(env.observation());
  ASSERT_NE(turned, start);
  rl::Env::Snapshot snap = env.snapshot();
  rl::StepResult original = env.step(kLookRight);
  std::vector<float> after = features(env.observation());

  env.reset(1, 5);
  EXPECT_EQ(features(env.reset_to(snap, 5)), turned);  // the saved picture, not the level start's
  rl::StepResult replay = env.step(kLookRight);
  EXPECT_EQ(features(env.observation()), after);
  EXPECT_EQ(replay.info.game_frames, original.info.game_frames);
  EXPECT_EQ(replay.info.score, original.info.score);
  EXPECT_EQ(replay.info.moves, 1u);  // a new episode: its counters restart
  EXPECT_EQ(original.info.moves, 2u);
}

TEST(StartStates, TrainingEpisodesStartFromSavedStatesTheSameOnEveryRun) {
  // P = 1: every training episode starts from a saved state once there is one; the first
  // episode's moves before its last are the first saved. Tests start from the level's start.
  std::string a = run_dir("a"), b = run_dir("b");
  Trainer first(tiny(a, 1.0)), second(tiny(b, 1.0));
  first.run(nullptr);
  second.run(nullptr);
  EXPECT_EQ(rows(first.records()), rows(second.records()));
  ASSERT_GT(first.records()[0].moves, 1u);
  for (const EpisodeRecord& r : first.records())
    EXPECT_EQ(r.saved_start, !r.test && r.episode > 1) << "episode " << r.episode;
  // The metric file's last column says the same: "saved" for those episodes, "level" for the rest.
  std::ifstream csv(a + "/metrics.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line.substr(line.rfind(',') + 1), "start");
  for (const EpisodeRecord& r : first.records()) {
    ASSERT_TRUE(std::getline(csv, line));
    EXPECT_EQ(line.substr(line.rfind(',') + 1), r.saved_start ? "saved" : "level") << line;
  }
  for (const auto& d : {a, b}) std::filesystem::remove_all(d);
}

TEST(StartStates, RefusesResumeAndBadProbabilities) {
  std::string dir = run_dir("refuse");
  TrainConfig c = tiny(dir, 0.5);
  c.episodes = 1;
  c.test_every = 2;
  {
    Trainer t(c);
    t.run(nullptr);
  }
  c.resume = true;
  try {
    Trainer t(c);
    ADD_FAILURE() << "resumed with saved states";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--resume needs --start-states 0"), std::string::npos) << e.what();
  }
  c.resume = false;
  c.start_states = 1.5;
  EXPECT_THROW(Trainer{c}, std::invalid_argument);
  std::filesystem::remove_all(dir);
}
