// The vector environments equal single environments bit for bit: 4 Tumble environments with
// automatic resets, stepped in batches (VecEnv, src/rl/vec_env.h) and asynchronously
// (AsyncVecEnv, src/rl/async_vec_env.h), against 4 single environments driven with the same
// actions and the documented seeds (episode_seed). Plus the thread pool's contract.
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <string>
#include <thread>

#include "rl/async_vec_env.h"
#include "rl/vec_env.h"
#include "sanitizer_scale.h"

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

// Sanitizer builds run the emulator several times slower; fewer steps still cover automatic
// resets there (random play on level 1 ends an episode every few moves).
constexpr int kSteps = test_scale::sized(60, 15);
constexpr int kEnvs = 4, kLevel = 1;
constexpr std::uint64_t kSeed = 2024;

namespace {

EnvConfig local_config() {
  EnvConfig config;
  config.obs = "local";
  return config;
}

// Environment i's t-th action, from a fixed linear congruential sequence (Numerical Recipes'
// constants).
int action_of(int i, int t) {
  std::uint32_t lcg = 12345u + static_cast<std::uint32_t>(t * kEnvs + i);
  for (int k = 0; k < 3; ++k) lcg = lcg * 1664525u + 1013904223u;
  return static_cast<int>((lcg >> 16) % 4);
}

// What one environment did: the observation after its reset (index 0) and after each move, and
// each move's reward and end flags (terminated | truncated << 1).
struct Trajectory {
  std::vector<std::vector<std::uint8_t>> obs;
  std::vector<double> rewards;
  std::vector<int> flags;
  int episodes_ended = 0;
};

// The reference: kEnvs single environments with the documented seeds (episode_seed), each on its
// own thread (they share nothing), computed once for the tests below.
const std::vector<Trajectory>& single_environments() {
  static const std::vector<Trajectory> runs = [] {
    std::vector<Trajectory> out(kEnvs);
    auto run = [&](int i) {
      Trajectory& tr = out[static_cast<size_t>(i)];
      Env env(local_config());
      std::uint64_t episode = 0;
      auto record = [&] {
        const auto& o = env.observation()[0];
        const auto* bytes = static_cast<const std::uint8_t*>(o.data);
        tr.obs.emplace_back(bytes, bytes + o.space->bytes());
      };
      env.reset(kLevel, episode_seed(kSeed, i, episode), nullptr);
      record();
      for (int t = 0; t < kSteps; ++t) {
        StepResult r = env.step(action_of(i, t));
        tr.rewards.push_back(r.reward);
        tr.flags.push_back(int(r.terminated) | int(r.truncated) << 1);
        if (r.terminated || r.truncated) {
          ++tr.episodes_ended;
          env.reset(kLevel, episode_seed(kSeed, i, ++episode), nullptr);
        }
        record();
      }
    };
    std::vector<std::thread> threads;
    for (int i = 0; i < kEnvs; ++i) threads.emplace_back(run, i);
    for (auto& t : threads) t.join();
    return out;
  }();
  return runs;
}

bool same_bytes(const std::vector<std::uint8_t>& a, const std::uint8_t* b) { return std::memcmp(a.data(), b, a.size()) == 0; }

}  // namespace

TEST(VecEnv, EqualsSingleEnvironmentsBitForBit) {
  const auto& ref = single_environments();
  VecEnv vec(local_config(), kEnvs, 2);
  vec.reset(kLevel, kSeed);
  const size_t bytes = vec.observation_spaces()[0].bytes();
  for (int i = 0; i < kEnvs; ++i) EXPECT_TRUE(same_bytes(ref[i].obs[0], vec.batch()[0].data() + i * bytes)) << "env " << i;
  std::vector<int> actions(kEnvs);
  for (int t = 0; t < kSteps; ++t) {
    for (int i = 0; i < kEnvs; ++i) actions[static_cast<size_t>(i)] = action_of(i, t);
    const VecStep& s = vec.step(actions);
    for (size_t i = 0; i < kEnvs; ++i) {
      const std::string at = "env " + std::to_string(i) + " step " + std::to_string(t);
      ASSERT_EQ(s.rewards[i], ref[i].rewards[static_cast<size_t>(t)]) << at;
      ASSERT_EQ(int(s.terminated[i]) | int(s.truncated[i]) << 1, ref[i].flags[static_cast<size_t>(t)]) << at;
      ASSERT_TRUE(same_bytes(ref[i].obs[static_cast<size_t>(t) + 1], vec.batch()[0].data() + i * bytes)) << at;
    }
  }
  int ended = 0;
  for (const auto& r : ref) ended += r.episodes_ended;
  EXPECT_GE(ended, 1);  // random play falls off level 1: auto-reset was exercised
}

// Asynchronous stepping returns environments in whatever order they finish, but each one's
// trajectory is the single environment's: 4 environments, batches of 2, on 2 threads.
TEST(AsyncVecEnv, EachEnvironmentEqualsItsSingleEnvironment) {
  const auto& ref = single_environments();
  AsyncVecEnv async(local_config(), kEnvs, 2, 2);
  async.reset(kLevel, kSeed);
  const size_t bytes = async.observation_spaces()[0].bytes();
  std::vector<int> moves(kEnvs, -1);  // moves whose result was checked; -1: reset not seen yet
  int checked = 0, batches = 0;
  while (checked < kEnvs * (kSteps + 1)) {
    const AsyncBatch& b = async.recv();
    ++batches;
    ASSERT_EQ(b.env_ids.size(), 2u);
    std::vector<int> ids, actions;
    for (size_t k = 0; k < b.env_ids.size(); ++k) {
      const int i = b.env_ids[k];
      int& done = moves[static_cast<size_t>(i)];
      if (++done <= kSteps) {
        const size_t t = static_cast<size_t>(done);
        const std::string at = "env " + std::to_string(i) + " after move " + std::to_string(t);
        ASSERT_TRUE(same_bytes(ref[i].obs[t], b.observations[0].data() + k * bytes)) << at;
        if (t > 0) {
          ASSERT_EQ(b.rewards[k], ref[i].rewards[t - 1]) << at;
          ASSERT_EQ(int(b.terminated[k]) | int(b.truncated[k]) << 1, ref[i].flags[t - 1]) << at;
        }
        ++checked;
      }
      // Environments past the compared moves keep playing so that a batch can always fill.
      ids.push_back(i);
      actions.push_back(done < kSteps ? action_of(i, done) : 0);
    }
    async.send(actions, ids);
  }
  EXPECT_GE(batches, kEnvs * (kSteps + 1) / 2);
}

TEST(AsyncVecEnv, RefusesMisuseWithAMessage) {
  EXPECT_THROW(AsyncVecEnv(local_config(), 2, 3, 1), std::invalid_argument);  // batch > envs
  AsyncVecEnv async(local_config(), 2, 1, 1);
  EXPECT_THROW(async.recv(), std::logic_error);  // nothing in flight yet
  async.reset(kLevel, kSeed);
  const AsyncBatch& b = async.recv();
  const int held = b.env_ids[0], busy = 1 - held;
  EXPECT_THROW(async.send({0}, {busy}), std::invalid_argument);      // still in flight
  EXPECT_THROW(async.send({0, 1}, {held, held}), std::invalid_argument);  // listed twice
  EXPECT_THROW(async.send({4}, {held}), std::invalid_argument);       // no such action
  EXPECT_THROW(async.send({0}, {7}), std::invalid_argument);          // no such environment
  async.send({0}, {held});  // the refusals changed nothing: a valid send still works
  EXPECT_EQ(async.recv().env_ids.size(), 1u);
}
