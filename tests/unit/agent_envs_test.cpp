// Training with K environments (--envs, src/rl/agents/trainer_loop.cpp): with one environment the
// trainer gives exactly what the documented single-environment loop gives, written out here
// against rl::Env; with two, the same command gives the same metrics twice; a run with several
// environments refuses --resume.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "rl/agents/trainer.h"
#include "rl/vec_env.h"

using namespace psxrl::agents;
namespace rl = psxrl::rl;

namespace {

std::string run_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("psxrl_agent_envs_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  return dir.string();
}

TrainConfig tiny(const std::string& out, int envs) {
  TrainConfig c;
  c.agent = "dqn";
  c.env.obs = "local";
  c.env.max_moves = 4;
  c.options.epochs = 2;
  c.episodes = 6;
  c.test_every = 3;
  c.seed = 21;
  c.envs = envs;
  c.out = out;
  return c;
}

std::string row(std::uint64_t episode, bool test, std::int64_t score, double reward, std::uint64_t moves,
                std::uint64_t frames, const std::string& outcome, double epsilon, double loss, std::uint64_t total) {
  std::ostringstream os;
  os.precision(17);
  os << episode << ' ' << test << ' ' << score << ' ' << reward << ' ' << moves << ' ' << frames << ' ' << outcome
     << ' ' << epsilon << ' ' << loss << ' ' << total;
  return os.str();
}

std::vector<std::string> rows(const std::vector<EpisodeRecord>& records) {
  std::vector<std::string> out;
  for (const EpisodeRecord& r : records)
    out.push_back(row(r.episode, r.test, r.score, r.reward, r.moves, r.frames, r.outcome, r.epsilon, r.loss,
                      r.total_moves));
  return out;
}

// The single-environment loop as docs/agents.md states it: episode k (1-based) starts with
// reset(level, episode_seed(seed, 0, k - 1)), is a greedy test when k is a multiple of
// test_every, and every training move is observed and learnt from.
std::vector<std::string> reference(TrainConfig c) {
  c.options.gamma = c.env.gamma;
  c.options.seed = c.seed;
  rl::Env env(c.env);
  auto agent = make_agent(c.agent, env.obs_kind(), env.observation_spaces(), env.action_count(), c.options);
  std::vector<std::string> out;
  for (std::uint64_t k = 1; k <= c.episodes; ++k) {
    bool test = k % static_cast<std::uint64_t>(c.test_every) == 0;
    rl::StepInfo start;
    std::vector<float> s = features(env.reset(c.level, rl::episode_seed(c.seed, 0, k - 1), &start));
    rl::StepResult r;
    std::uint64_t frames = start.game_frames;  // an episode's frames include its level's start
    do {
      int a = agent->act(s, test);
      r = env.step(a);
      std::vector<float> next = features(env.observation());
      if (!test) {
        agent->observe({s, a, r.reward, next, r.terminated});
        agent->learn();
      }
      s = next;
      frames += r.info.game_frames;
    } while (!r.terminated && !r.truncated);
    out.push_back(row(k, test, r.info.score, r.info.episode_reward, r.info.moves, frames,
                      r.info.outcome.empty() ? "truncated" : r.info.outcome, agent->epsilon(), agent->last_loss(),
                      agent->moves()));
  }
  return out;
}

}  // namespace

TEST(Envs, OneEnvironmentIsTheSingleEnvironmentLoop) {
  std::string dir = run_dir("one");
  Trainer t(tiny(dir, 1));
  t.run(nullptr);
  EXPECT_EQ(rows(t.records()), reference(tiny(dir, 1)));
  std::filesystem::remove_all(dir);
}

TEST(Envs, TwoEnvironmentsGiveTheSameMetricsTwice) {
  std::string a = run_dir("two_a"), b = run_dir("two_b");
  Trainer first(tiny(a, 2)), second(tiny(b, 2));
  first.run(nullptr);
  second.run(nullptr);
  ASSERT_EQ(first.records().size(), 6u);
  EXPECT_EQ(rows(first.records()), rows(second.records()));
  // Training moves of both environments count: at least those of the recorded training episodes.
  std::uint64_t recorded = 0;
  for (const EpisodeRecord& r : first.records())
    if (!r.test) recorded += r.moves;
  EXPECT_GE(first.records().back().total_moves, recorded);
  std::filesystem::remove_all(a);
  std::filesystem::remove_all(b);
}

TEST(Envs, SeveralEnvironmentsRefuseResume) {
  std::string dir = run_dir("resume");
  TrainConfig c = tiny(dir, 2);
  c.episodes = 1;
  {
    Trainer t(c);
    t.run(nullptr);
  }
  c.resume = true;
  c.episodes = 2;
  try {
    Trainer t(c);
    ADD_FAILURE() << "resumed a run of 2 environments";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--resume needs --envs 1"), std::string::npos) << e.what();
  }
  c.envs = 1;  // the run's own setting differs
  try {
    Trainer t(c);
    ADD_FAILURE() << "resumed a run of 2 environments with 1";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("envs = 2, this command has envs = 1"), std::string::npos) << e.what();
  }
  c.envs = 0;
  c.resume = false;
  EXPECT_THROW(Trainer{c}, std::invalid_argument);
  std::filesystem::remove_all(dir);
}
