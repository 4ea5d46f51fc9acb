// Environment throughput on Tumble level 1: moves per second for one environment and for the
// vector environment at 1 and 2 threads, per observation kind, and host memory per environment
// (resident set growth divided by the number of environments). Actions follow a fixed sequence;
// episodes that end are reset, as in training.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "rl/vec_env.h"

namespace {

using Clock = std::chrono::steady_clock;
using namespace psxrl::rl;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

long resident_kib() {
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

int action_at(std::uint32_t& lcg) { return static_cast<int>(((lcg = lcg * 1664525u + 1013904223u) >> 16) % 4); }

double single_moves_per_second(const std::string& obs, int moves) {
  EnvConfig c;
  c.obs = obs;
  Env env(c);
  std::uint64_t seed = 1;
  env.reset(1, seed, nullptr);
  std::uint32_t lcg = 7;
  auto t = Clock::now();
  for (int i = 0; i < moves; ++i) {
    auto r = env.step(action_at(lcg));
    if (r.terminated || r.truncated) env.reset(1, ++seed, nullptr);
  }
  return moves / seconds_since(t);
}

double vec_moves_per_second(const std::string& obs, int envs, unsigned threads, int steps) {
  EnvConfig c;
  c.obs = obs;
  VecEnv vec(c, envs, threads);
  vec.reset(1, 1);
  std::uint32_t lcg = 7;
  std::vector<int> actions(static_cast<size_t>(envs));
  auto t = Clock::now();
  for (int s = 0; s < steps; ++s) {
    for (auto& a : actions) a = action_at(lcg);
    vec.step(actions);
  }
  return static_cast<double>(steps) * envs / seconds_since(t);
}

}  // namespace

int main() {
  std::printf("psxrl environment benchmark: Tumble level 1, random actions (fixed sequence)\n\n");
  std::printf("| observation | 1 env moves/s | vec 2 envs, 1 thread | vec 2 envs, 2 threads |\n");
  std::printf("| --- | --- | --- | --- |\n");
  for (const char* obs : {"simple", "local", "episode", "ram", "visual", "audio", "multimodal"}) {
    double one = single_moves_per_second(obs, 150);
    double v1 = vec_moves_per_second(obs, 2, 1, 75);
    double v2 = vec_moves_per_second(obs, 2, 2, 75);
    std::printf("| %s | %.1f | %.1f | %.1f (x%.2f) |\n", obs, one, v1, v2, v2 / v1);
  }
  long before = resident_kib();
  {
    EnvConfig c;
    c.obs = "simple";
    std::vector<std::unique_ptr<Env>> envs;
    for (int i = 0; i < 8; ++i) envs.push_back(std::make_unique<Env>(c));
    for (auto& e : envs) e->reset(1, 1, nullptr);
    std::printf("\nhost memory per environment (8 environments, simple): %.1f MiB\n",
                static_cast<double>(resident_kib() - before) / 1024 / 8);
  }
  return 0;
}
