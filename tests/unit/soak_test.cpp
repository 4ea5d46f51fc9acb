// A short soak (#61; bench/soak_bench.cpp runs the long one): 50,000 Tumble moves across resets
// on one environment must not grow host memory. The resident set is taken after 5,000 moves (the
// recompiler has compiled the level's code, maps and buffers exist, the allocator holds its
// pools) and again at the end. The bound, 4 MiB, is what a leak of 94 bytes a move would add over
// the remaining 45,000 moves; an environment keeps nothing per move, so growth should be near 0.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

#include "rl/env.h"

namespace {

long resident_kib() {
  std::ifstream status("/proc/self/status");
  for (std::string key; status >> key;) {
    if (key == "VmRSS:") {
      long kib = 0;
      status >> kib;
      return kib;
    }
    status.ignore(1 << 20, '\n');
  }
  return 0;
}

TEST(Soak, FiftyThousandMovesKeepHostMemoryFlat) {
  constexpr int kMoves = 50'000, kWarmup = 5'000;
  constexpr long kBoundKib = 4 * 1024;
  psxrl::rl::EnvConfig c;
  c.obs = "simple";
  psxrl::rl::Env env(c);
  std::uint64_t seed = 1, episodes = 1;
  env.reset(1, seed, nullptr);
  std::uint32_t lcg = 7;
  long after_warmup = 0;
  for (int i = 0; i < kMoves; ++i) {
    if (i == kWarmup) after_warmup = resident_kib();
    lcg = lcg * 1664525u + 1013904223u;  // Numerical Recipes' LCG: a fixed action sequence
    psxrl::rl::StepResult r = env.step(static_cast<int>((lcg >> 16) % 4));
    if (r.terminated || r.truncated) env.reset(1, ++seed, nullptr), ++episodes;
  }
  const long growth = resident_kib() - after_warmup;
  std::printf("resident set %ld KiB after %d moves, %+ld KiB after %d (%llu episodes)\n", after_warmup, kWarmup, growth,
              kMoves, static_cast<unsigned long long>(episodes));
  EXPECT_GT(episodes, 100u) << "the moves must cross many resets";
  EXPECT_LE(growth, kBoundKib) << "resident set grew " << growth << " KiB over " << kMoves - kWarmup << " moves";
}

}  // namespace
