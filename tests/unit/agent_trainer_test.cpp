// The training loop on Tumble (src/rl/agents/trainer.h): a run stopped after 3 episodes and
// resumed from its checkpoint records the same 6 episodes as an uninterrupted run; a resume with
// other settings, and a new run over an old one, are refused. Episodes are capped at a few moves
// to keep the test short (a move is about 20 emulated frames).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "rl/agents/learning_curve.h"
#include "rl/agents/trainer.h"

using namespace psxrl::agents;

namespace {

std::string run_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("psxrl_agent_train_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir.string();
}

TrainConfig tiny(const std::string& agent, const std::string& out, std::uint64_t episodes) {
  TrainConfig c;
  c.agent = agent;
  c.env.obs = default_obs(agent);
  c.env.max_moves = 4;
  c.options.epochs = 2;
  c.episodes = episodes;
  c.test_every = 3;  // episodes 3 and 6 are greedy tests
  c.seed = 11;
  c.out = out;
  return c;
}

// Everything a record holds but the host time, which no run reproduces.
std::vector<std::string> without_time(const std::vector<EpisodeRecord>& records) {
  std::vector<std::string> rows;
  for (const EpisodeRecord& r : records) {
    std::ostringstream os;
    os.precision(17);
    os << r.episode << ' ' << r.test << ' ' << r.score << ' ' << r.reward << ' ' << r.moves << ' ' << r.frames << ' '
       << r.outcome << ' ' << r.epsilon << ' ' << r.loss << ' ' << r.total_moves;
    rows.push_back(os.str());
  }
  return rows;
}

size_t lines(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  size_t n = 0;
  while (std::getline(in, line)) ++n;
  return n;
}

void expect_resume_equals_uninterrupted(const std::string& agent) {
  std::string whole = run_dir(agent + "_whole"), split = run_dir(agent + "_split");
  Trainer a(tiny(agent, whole, 6));
  a.run(nullptr);
  ASSERT_EQ(a.records().size(), 6u);
  {
    Trainer first(tiny(agent, split, 3));
    first.run(nullptr);
  }
  TrainConfig c = tiny(agent, split, 6);
  c.resume = true;
  Trainer resumed(c);
  resumed.run(nullptr);
  EXPECT_EQ(without_time(resumed.records()), without_time(a.records()));
  EXPECT_EQ(lines(split + "/metrics.csv"), 7u);  // header + 6 episodes
  EXPECT_EQ(lines(split + "/metrics.jsonl"), 6u);
  EXPECT_TRUE(std::filesystem::exists(split + "/learning_curve.png"));
  std::filesystem::remove_all(whole);
  std::filesystem::remove_all(split);
}

}  // namespace

TEST(Trainer, QResumeContinuesExactly) { expect_resume_equals_uninterrupted("q"); }
TEST(Trainer, DqnResumeContinuesExactly) { expect_resume_equals_uninterrupted("dqn"); }

TEST(Trainer, RefusesMismatchedResumeAndOverwrite) {
  std::string dir = run_dir("refuse");
  {
    Trainer t(tiny("q", dir, 1));
    t.run(nullptr);
  }
  EXPECT_THROW(Trainer(tiny("q", dir, 2)), std::invalid_argument);  // a run is there: --resume or another --out
  TrainConfig other = tiny("q", dir, 2);
  other.resume = true;
  other.seed = 12;
  try {
    Trainer t(other);
    ADD_FAILURE() << "resumed with another seed";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("seed = 11, this command has seed = 12"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(Trainer, RefusesUnknownNamesAndLevels) {
  std::string dir = run_dir("names");
  TrainConfig c = tiny("q", dir, 1);
  c.level = 11;  // Tumble has 10
  EXPECT_THROW(Trainer{c}, std::invalid_argument);
  c = tiny("nope", dir, 1);
  c.env.obs = "simple";
  EXPECT_THROW(Trainer{c}, std::invalid_argument);
  std::filesystem::remove_all(dir);
}

TEST(LearningCurve, MovingAverageOverFive) {
  // (1) (1+2)/2 (1+2+3)/3 ... then windows of 5: (2+3+4+5+6)/5 = 4.
  EXPECT_EQ(moving_average({1, 2, 3, 4, 5, 6}, 5), (std::vector<double>{1, 1.5, 2, 2.5, 3, 4}));
}
