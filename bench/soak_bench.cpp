// Soak (#61): one million Tumble moves across resets, on one environment and on a vector
// environment of 8, with host memory (resident set) and moves per second every 100,000 moves.
// A leak shows as memory that keeps growing after the first report (the recompiler's code and
// the allocator's pools are in place by then); a slowdown as moves/s falling from window to
// window. Actions follow a fixed pseudo-random sequence; episodes that end are reset, as in
// training. Usage: soak_bench [MOVES [EVERY [ENVS]]] (default 1000000, 100000, and both 1 and 8
// environments; ENVS 1 or 8 runs only that soak, so the two can run side by side).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>
#include <vector>

#include "bench_util.h"

using namespace psxrl::rl;

namespace {

// Steps `envs` environments (1: a single Env, else a VecEnv with a thread per environment up to
// the host's cores) for `moves` moves, reporting every `every` moves.
void soak(int envs, long moves, long every) {
  EnvConfig c;
  c.obs = "simple";
  std::unique_ptr<Env> one;
  std::unique_ptr<VecEnv> vec;
  std::uint64_t seed = 1;
  if (envs == 1) {
    one = std::make_unique<Env>(c);
    one->reset(1, seed, nullptr);
  } else {
    unsigned threads = std::min<unsigned>(static_cast<unsigned>(envs), std::max(1u, std::thread::hardware_concurrency()));
    vec = std::make_unique<VecEnv>(c, envs, threads);
    vec->reset(1, seed);
  }
  std::printf("\n%d environment%s, %ld moves\n| moves | resident MiB | moves/s in the window |\n| --- | --- | --- |\n",
              envs, envs == 1 ? "" : "s (VecEnv)", moves);
  std::uint32_t lcg = 7;
  std::vector<int> actions(static_cast<size_t>(envs));
  long done = 0, next_report = every;
  double first_rate = 0, last_rate = 0, first_mib = 0, last_mib = 0;
  auto window = bench::Clock::now();
  while (done < moves) {
    for (auto& a : actions) a = bench::action_at(lcg);
    if (one) {
      StepResult r = one->step(actions[0]);
      if (r.terminated || r.truncated) one->reset(1, ++seed, nullptr);
    } else {
      vec->step(actions);
    }
    done += envs;
    if (done >= next_report) {
      const double rate = static_cast<double>(every) / bench::seconds_since(window);
      const double mib = static_cast<double>(bench::resident_kib()) / 1024;
      if (next_report == every) first_rate = rate, first_mib = mib;
      last_rate = rate, last_mib = mib;
      std::printf("| %ld | %.1f | %.0f |\n", next_report, mib, rate);
      std::fflush(stdout);
      next_report += every;
      window = bench::Clock::now();
    }
  }
  std::printf("memory after the first report: %+.1f MiB; moves/s, last window against the first: %+.1f%%\n",
              last_mib - first_mib, first_rate > 0 ? 100 * (last_rate / first_rate - 1) : 0.0);
}

}  // namespace

int main(int argc, char** argv) {
  const long moves = argc > 1 ? std::atol(argv[1]) : 1'000'000;
  const long every = argc > 2 ? std::atol(argv[2]) : 100'000;
  const long envs = argc > 3 ? std::atol(argv[3]) : 0;
  if (moves < 1 || every < 1 || (envs != 0 && envs != 1 && envs != 8)) {
    std::fprintf(stderr, "usage: soak_bench [MOVES [EVERY [ENVS]]] (MOVES, EVERY at least 1; ENVS 1 or 8)\n");
    return 1;
  }
  std::printf("psxrl soak: Tumble level 1, observation simple, fixed random actions\n");
  if (envs != 8) soak(1, moves, every);
  if (envs != 1) soak(8, moves, every);
  return 0;
}
