// The seed's Q-weighted exploration (Eq. 4.1, §4.2.4): action probabilities proportional to
// K(a) = Q(s|a) + rand(-0.5, 0.5) * range(Q), worked by hand for given Q-values and noise, and an
// agent that explores with them.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>

#include "rl/agents/checkpoint.h"
#include "rl/agents/q_agent.h"
#include "rl/agents/trainer.h"

using namespace psxrl::agents;

namespace {

void expect_probabilities(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (size_t a = 0; a < want.size(); ++a) EXPECT_NEAR(got[a], want[a], 1e-12) << "action " << a;
}

// A tabular agent that explores on every training move (ε = 1) with `e`, and has learnt
// Q(5, a) = q[a] (alpha 1 on terminal transitions sets the value to the reward).
QAgent explorer(Exploration e, const std::array<double, 4>& q, std::uint64_t seed) {
  AgentOptions o;
  o.alpha = 1;
  o.epsilon_start = o.epsilon_end = 1;
  o.exploration = e;
  o.seed = seed;
  QAgent agent(o, 4);
  for (int a = 0; a < 4; ++a) agent.observe({{5}, a, q[static_cast<size_t>(a)], {6}, true});
  return agent;
}

std::array<int, 4> counts(QAgent& agent, int draws) {
  std::array<int, 4> n{};
  for (int i = 0; i < draws; ++i) ++n[static_cast<size_t>(agent.act({5}, false))];
  return n;
}

}  // namespace

TEST(QWeighted, ProbabilitiesAreProportionalToK) {
  // Q = (0.2, 0.5, -0.3, 0.1): range 0.5 - (-0.3) = 0.8. Without noise K = Q; the negative K
  // weighs 0: (0.2, 0.5, 0, 0.1) / 0.8.
  expect_probabilities(q_weighted_probabilities({0.2, 0.5, -0.3, 0.1}, {0, 0, 0, 0}), {0.25, 0.625, 0, 0.125});
  // Noise (0.5, -0.5, 0.5, 0) adds (0.4, -0.4, 0.4, 0): K = (0.6, 0.1, 0.1, 0.1), sum 0.9.
  expect_probabilities(q_weighted_probabilities({0.2, 0.5, -0.3, 0.1}, {0.5, -0.5, 0.5, 0}),
                       {0.6 / 0.9, 0.1 / 0.9, 0.1 / 0.9, 0.1 / 0.9});
  // Noise (-0.25, 0.25, 0, -0.5) adds (-0.2, 0.2, 0, -0.4): K = (0, 0.7, -0.3, -0.3).
  expect_probabilities(q_weighted_probabilities({0.2, 0.5, -0.3, 0.1}, {-0.25, 0.25, 0, -0.5}), {0, 1, 0, 0});
}

TEST(QWeighted, EqualOrAllNegativeValuesGiveAUniformChoice) {
  // Equal values: range 0, so the noise adds nothing and K = 0.3 for every action.
  expect_probabilities(q_weighted_probabilities({0.3, 0.3, 0.3, 0.3}, {0.4, -0.2, 0.1, -0.5}), {0.25, 0.25, 0.25, 0.25});
  // Every K below 0: no action weighs anything, so none is preferred.
  expect_probabilities(q_weighted_probabilities({-0.5, -0.6, -0.7, -0.8}, {0, 0, 0, 0}), {0.25, 0.25, 0.25, 0.25});
}

TEST(QWeighted, ExplorationAvoidsActionsWhoseKIsNeverPositive) {
  // Q = (0.9, -0.9, -0.9, -0.9): range 1.8, so K(0) = 0.9 + 1.8 n lies in [0, 1.8) and every
  // other K = -0.9 + 1.8 n in [-1.8, 0): exploring always picks action 0.
  QAgent weighted = explorer(Exploration::QWeighted, {0.9, -0.9, -0.9, -0.9}, 1);
  EXPECT_EQ(counts(weighted, 2000)[0], 2000);
  // Uniform exploration picks each action about a quarter of the time: 500 +- 5 sigma,
  // sigma = sqrt(2000 * 0.25 * 0.75) = 19.4.
  QAgent uniform = explorer(Exploration::Epsilon, {0.9, -0.9, -0.9, -0.9}, 1);
  for (int n : counts(uniform, 2000)) EXPECT_NEAR(n, 500, 97);
}

TEST(QWeighted, EqualValuesExploreUniformly) {
  QAgent weighted = explorer(Exploration::QWeighted, {0.4, 0.4, 0.4, 0.4}, 2);
  for (int n : counts(weighted, 4000)) EXPECT_NEAR(n, 1000, 137);  // sigma = sqrt(4000 * 3 / 16) = 27.4
}

TEST(QWeighted, NamesParse) {
  EXPECT_EQ(parse_exploration("epsilon"), Exploration::Epsilon);
  EXPECT_EQ(parse_exploration("q-weighted"), Exploration::QWeighted);
  EXPECT_STREQ(exploration_name(Exploration::QWeighted), "q-weighted");
  EXPECT_THROW(parse_exploration("boltzmann"), std::invalid_argument);
}

TEST(QWeighted, IsARunSettingThatResumeChecks) {
  auto dir = std::filesystem::temp_directory_path() / ("psxrl_agent_qweighted_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  TrainConfig c;
  c.agent = "q";
  c.env.obs = "simple";
  c.env.max_moves = 3;
  c.episodes = 1;
  c.out = dir.string();
  c.options.exploration = Exploration::QWeighted;
  {
    Trainer t(c);
    t.run(nullptr);
  }
  EXPECT_EQ(read_checkpoint(checkpoint_path(c.out)).meta.at("exploration"), "q-weighted");
  c.resume = true;
  c.episodes = 2;
  c.options.exploration = Exploration::Epsilon;
  try {
    Trainer t(c);
    ADD_FAILURE() << "resumed with other exploration";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("exploration = q-weighted, this command has exploration = epsilon"),
              std::string::npos)
        << e.what();
  }
  // A checkpoint from before the setting existed read as the uniform exploration every run had.
  Checkpoint old = read_checkpoint(checkpoint_path(c.out));
  old.meta.erase("exploration");
  TrainConfig applied;
  apply_settings(old.meta, applied);
  EXPECT_EQ(applied.options.exploration, Exploration::Epsilon);
  std::filesystem::remove_all(dir);
}
