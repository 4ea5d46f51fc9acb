// Start positions as walks (--start, --test-start; seed §4.2.6). Expected places come from level
// 1's map (games/tumble/levels/level01.txt: S at column 2, row 5, facing north; coins at columns 1
// and 3 of rows 1 and 3-5) and the moves of games/tumble/README.md: FORWARD rolls one tile, JUMP
// FORWARD lands two tiles on (over the next), a LOOK turns the facing 90 degrees.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "rl/agents/trainer.h"

using namespace psxrl::agents;
namespace rl = psxrl::rl;

namespace {

std::string run_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("psxrl_agent_walk_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir.string();
}

struct Place {
  double x, y, facing, score;
  bool operator==(const Place&) const = default;
};

Place place(const rl::Env& env) {
  return {env.value("ball_x"), env.value("ball_y"), env.value("facing"), env.value("score")};
}

TrainConfig tiny(const std::string& out) {
  TrainConfig c;
  c.agent = "q";
  c.env.obs = "simple";
  c.env.max_moves = 3;
  c.episodes = 4;
  c.test_every = 2;
  c.seed = 3;
  c.out = out;
  return c;
}

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(StartPosition, WalksEndWhereTheMapAndMovesSay) {
  rl::Env env(rl::EnvConfig{});
  struct Case {
    const char* walk;
    Place at;
  } cases[] = {
      {"", {2, 5, 0, 0}},                                      // the level's own start
      {"FORWARD,FORWARD", {2, 3, 0, 0}},                       // up the item-free column 2
      {"LOOKLEFT,JUMPFORWARD", {0, 5, 3, 0}},                  // west, over the coin at column 1
      {"lookright,3,LOOKLEFT,FORWARD", {4, 4, 0, 0}},          // names in any case, numbers
  };
  for (const Case& c : cases) {
    rl::StepInfo info;
    begin_at(env, 1, parse_start_position(c.walk, env.actions()), 1, &info);
    EXPECT_EQ(place(env), c.at) << c.walk;
    EXPECT_EQ(info.moves, 0u) << c.walk;  // the episode begins after the walk
    EXPECT_FALSE(env.episode_over()) << c.walk;
  }
}

TEST(StartPosition, WalksThatCollectOrEndAreRefused) {
  rl::Env env(rl::EnvConfig{});
  auto walk = [&](const char* text) { begin_at(env, 1, parse_start_position(text, env.actions()), 1, nullptr); };
  EXPECT_THROW(walk("LOOKLEFT,FORWARD"), std::invalid_argument);                         // the coin at (1, 5)
  EXPECT_THROW(walk("LOOKLEFT,JUMPFORWARD,JUMPFORWARD"), std::invalid_argument);        // off the west edge
  EXPECT_THROW(parse_start_position("FORWARD,BACK", env.actions()), std::invalid_argument);
  EXPECT_THROW(parse_start_position("FORWARD,", env.actions()), std::invalid_argument);
  EXPECT_THROW(parse_start_position("4", env.actions()), std::invalid_argument);         // actions 0 to 3
}

// 4 episodes with a test every 2nd: tests at episodes 2 and 4, each followed by one held-out
// greedy episode per --test-start, numbered as their test and not counted in the 4.
TEST(StartPosition, HeldOutTestsFollowEveryTest) {
  TrainConfig c = tiny(run_dir("heldout"));
  c.test_starts = {"FORWARD", "LOOKLEFT,JUMPFORWARD"};
  Trainer t(c);
  t.run(nullptr);
  std::vector<std::string> got;
  for (const EpisodeRecord& r : t.records())
    got.push_back(std::to_string(r.episode) + (r.heldout ? " heldout " + std::to_string(r.heldout) : r.test ? " test" : " train"));
  EXPECT_EQ(got, (std::vector<std::string>{"1 train", "2 test", "2 heldout 1", "2 heldout 2", "3 train", "4 test",
                                           "4 heldout 1", "4 heldout 2"}));
  std::string csv = file_text(c.out + "/metrics.csv");
  EXPECT_NE(csv.find(",heldout-2\n"), std::string::npos);
  EXPECT_NE(file_text(c.out + "/config.json").find("\"test_starts\": \"FORWARD;LOOKLEFT,JUMPFORWARD\""), std::string::npos);
  std::filesystem::remove_all(c.out);
}

TEST(StartPosition, BadWalksAndHeldOutWithManyEnvsAreBadInput) {
  TrainConfig c = tiny(run_dir("bad"));
  c.start = "LOOKRIGHT,FORWARD";  // the coin at (3, 5)
  EXPECT_THROW(Trainer{c}, std::invalid_argument);
  c.start = "";
  c.test_starts = {"FORWARD"};
  c.envs = 2;
  EXPECT_THROW(Trainer{c}, std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(c.out + "/config.json"));
  std::filesystem::remove_all(c.out);
}

// config.json records the run's start, and target_network true with --double-dqn alone, as the DQN
// agent then bootstraps from its target network (dqn_agent.cpp).
TEST(StartPosition, StartIsRecordedAndDoubleDqnRecordsItsTargetNetwork) {
  TrainConfig c = tiny(run_dir("start"));
  c.start = "FORWARD,FORWARD";
  c.options.double_dqn = true;  // the DQN bootstraps from its target network with it (dqn_agent.cpp)
  Trainer t(c);
  std::string config = file_text(c.out + "/config.json");
  EXPECT_NE(config.find("\"start\": \"FORWARD,FORWARD\""), std::string::npos);
  EXPECT_NE(config.find("\"target_network\": \"true\""), std::string::npos);
  EXPECT_NE(config.find("\"test_starts\": \"none\""), std::string::npos);
  std::filesystem::remove_all(c.out);
}
