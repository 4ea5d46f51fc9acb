// Measurements shared by the benchmark programs (env_bench, psxrl_bench): timing, resident
// memory, and environment throughput on Tumble level 1 with a fixed pseudo-random action
// sequence, resetting episodes that end as training does. The host clock is used only to time.
#pragma once
#include <chrono>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "rl/async_vec_env.h"
#include "rl/vec_env.h"

namespace bench {

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// This process's resident set (VmRSS) in KiB.
inline long resident_kib() {
  std::ifstream status("/proc/self/status");
  std::string key;
  long value = 0;
  while (status >> key) {
    if (key == "VmRSS:") {
      status >> value;
      return value;
    }
    status.ignore(1 << 20, '\n');
  }
  return 0;
}

inline int action_at(std::uint32_t& lcg) { return static_cast<int>(((lcg = lcg * 1664525u + 1013904223u) >> 16) % 4); }

// Moves per second of one environment with observation kind `obs`.
// The first `warmup` moves are not timed: the recompiler compiles the level's code during an
// environment's first moves (about 1150 blocks in 300 moves), which a long training run pays once.
inline double single_moves_per_second(const std::string& obs, int moves, int warmup = 0) {
  psxrl::rl::EnvConfig c;
  c.obs = obs;
  psxrl::rl::Env env(c);
  std::uint64_t seed = 1;
  env.reset(1, seed, nullptr);
  std::uint32_t lcg = 7;
  auto t = Clock::now();
  for (int i = -warmup; i < moves; ++i) {
    if (i == 0) t = Clock::now();
    auto r = env.step(action_at(lcg));
    if (r.terminated || r.truncated) env.reset(1, ++seed, nullptr);
  }
  return moves / seconds_since(t);
}

// Moves per second (all environments together) of a vector environment, after `warmup` steps.
inline double vec_moves_per_second(const std::string& obs, int envs, unsigned threads, int steps, int warmup = 0) {
  psxrl::rl::EnvConfig c;
  c.obs = obs;
  psxrl::rl::VecEnv vec(c, envs, threads);
  vec.reset(1, 1);
  std::uint32_t lcg = 7;
  std::vector<int> actions(static_cast<size_t>(envs));
  auto t = Clock::now();
  for (int s = -warmup; s < steps; ++s) {
    if (s == 0) t = Clock::now();
    for (auto& a : actions) a = action_at(lcg);
    vec.step(actions);
  }
  return static_cast<double>(steps) * envs / seconds_since(t);
}

// Moves per second of an asynchronous vector environment (EnvPool's send/recv): `moves` moves
// in all after `warmup`, each batch of the first `batch` environments to finish sent straight back.
inline double async_moves_per_second(const std::string& obs, int envs, int batch, unsigned threads, int moves,
                                     int warmup = 0) {
  psxrl::rl::EnvConfig c;
  c.obs = obs;
  psxrl::rl::AsyncVecEnv vec(c, envs, batch, threads);
  vec.reset(1, 1);
  for (int k = 0; k < envs / batch; ++k) vec.recv();  // the resets
  std::vector<int> ids(static_cast<size_t>(envs));
  for (int i = 0; i < envs; ++i) ids[static_cast<size_t>(i)] = i;
  std::uint32_t lcg = 7;
  std::vector<int> actions(ids.size());
  for (auto& a : actions) a = action_at(lcg);
  auto t = Clock::now();
  vec.send(actions, ids);
  int done = -warmup;
  while (done < moves) {
    const psxrl::rl::AsyncBatch& b = vec.recv();
    done += batch;
    if (done >= 0 && done < batch) t = Clock::now(), done = 0;  // the warm-up ends here
    actions.resize(b.env_ids.size());
    for (auto& a : actions) a = action_at(lcg);
    vec.send(actions, b.env_ids);
  }
  const double s = seconds_since(t);
  return done / s;
}

}  // namespace bench
