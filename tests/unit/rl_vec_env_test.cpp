// The vector environment (src/rl/vec_env.h) equals single environments bit for bit: 4 Tumble
// environments on 2 threads over 200 batched steps with automatic resets, against 4 single
// environments driven one after another with the documented seeds (episode_seed). Plus the
// thread pool's contract.
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <string>
#include <thread>

#include "rl/vec_env.h"

using namespace psxrl::rl;

TEST(ThreadPool, RunsEveryIndexOnceAndRethrows) {
  ThreadPool pool(3);
  std::vector<std::atomic<int>> hits(100);
  pool.parallel_for(hits.size(), [&](size_t i) { hits[i]++; });
  for (auto& h : hits) EXPECT_EQ(h.load(), 1);
  EXPECT_THROW(pool.parallel_for(10, [](size_t i) { if (i == 7) throw std::runtime_error("x"); }), std::runtime_error);
  pool.parallel_for(5, [&](size_t i) { hits[i]++; });  // still usable
  EXPECT_EQ(hits[4].load(), 2);
}

TEST(EpisodeSeed, DistinctInputsGiveDistinctSeeds) {
  EXPECT_NE(episode_seed(1, 0, 0), episode_seed(1, 1, 0));
  EXPECT_NE(episode_seed(1, 0, 0), episode_seed(1, 0, 1));
  EXPECT_NE(episode_seed(1, 0, 0), episode_seed(2, 0, 0));
  EXPECT_EQ(episode_seed(5, 3, 2), episode_seed(5, 3, 2));
}

// Sanitizer builds run the emulator several times slower; an eighth of the steps still covers
// automatic resets there.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kSteps = 25;
#else
constexpr int kSteps = 200;
#endif

TEST(VecEnv, EqualsSingleEnvironmentsBitForBit) {
  constexpr int kEnvs = 4, kLevel = 1;
  constexpr std::uint64_t kSeed = 2024;
  EnvConfig config;
  config.obs = "local";
  // Actions from a fixed linear congruential sequence (Numerical Recipes' constants).
  std::vector<std::vector<int>> actions(kSteps, std::vector<int>(kEnvs));
  std::uint32_t lcg = 12345;
  for (auto& row : actions)
    for (auto& a : row) a = static_cast<int>(((lcg = lcg * 1664525u + 1013904223u) >> 16) % 4);

  VecEnv vec(config, kEnvs, 2);
  vec.reset(kLevel, kSeed);
  const size_t bytes = vec.observation_spaces()[0].bytes();
  std::vector<std::vector<std::uint8_t>> vec_obs;
  std::vector<double> vec_rewards;
  std::vector<int> vec_done;
  for (int t = 0; t < kSteps; ++t) {
    const VecStep& s = vec.step(actions[static_cast<size_t>(t)]);
    vec_obs.push_back(vec.batch()[0]);
    for (int i = 0; i < kEnvs; ++i) {
      vec_rewards.push_back(s.rewards[static_cast<size_t>(i)]);
      vec_done.push_back(s.terminated[static_cast<size_t>(i)] | s.truncated[static_cast<size_t>(i)] << 1);
    }
  }

  // The single environments, each on its own thread (they share nothing), so the test's wall
  // time on two cores is half of running them one after another.
  std::atomic<int> episodes_ended = 0;
  std::vector<std::string> failures(kEnvs);
  auto single = [&](int i) {
    Env env(config);
    std::uint64_t episode = 0;
    env.reset(kLevel, episode_seed(kSeed, i, episode), nullptr);
    for (int t = 0; t < kSteps && failures[static_cast<size_t>(i)].empty(); ++t) {
      StepResult r = env.step(actions[static_cast<size_t>(t)][static_cast<size_t>(i)]);
      size_t k = static_cast<size_t>(t * kEnvs + i);
      std::string at = "env " + std::to_string(i) + " step " + std::to_string(t) + ": ";
      if (r.reward != vec_rewards[k]) failures[static_cast<size_t>(i)] = at + "reward differs";
      if ((int(r.terminated) | int(r.truncated) << 1) != vec_done[k]) failures[static_cast<size_t>(i)] = at + "flags differ";
      if (r.terminated || r.truncated) {
        ++episodes_ended;
        env.reset(kLevel, episode_seed(kSeed, i, ++episode), nullptr);
      }
      if (std::memcmp(env.observation()[0].data, vec_obs[static_cast<size_t>(t)].data() + static_cast<size_t>(i) * bytes,
                      bytes) != 0)
        failures[static_cast<size_t>(i)] = at + "observation differs";
    }
  };
  std::vector<std::thread> threads;
  for (int i = 0; i < kEnvs; ++i) threads.emplace_back(single, i);
  for (auto& t : threads) t.join();
  for (const auto& f : failures) EXPECT_EQ(f, "");
  EXPECT_GE(episodes_ended.load(), 1);  // random play falls off level 1: auto-reset was exercised
}
