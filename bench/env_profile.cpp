// The Tumble environment's steady state for profilers: one environment on level 1, `warmup`
// moves (the recompiler compiles the level's code then), then `moves` moves inside
// measured_moves(), the function to give callgrind or perf. It is in an anonymous namespace, so
// callgrind needs `'--toggle-collect=*measured_moves*'` (the bare name matches nothing).
// Prints emulated cycles and CPU instructions per move and a hash of RAM, which a change meant to
// be bit-identical must leave as they were, what idle skipping skipped and what the recompiler
// compiled. Actions and resets are bench_util.h's, as in env_bench.
//   valgrind --tool=callgrind '--toggle-collect=*measured_moves*' build/bench/env_profile 200 100
// With --perf-map as the last argument it also names the compiled blocks for perf, which then
// reports the time of each (psx_block_<pc>) instead of bare addresses:
//   perf record -e cpu-clock build/bench/env_profile 200 600 simple --perf-map; perf report
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <utility>

#include "bench_util.h"
#include "core/hash.h"

using namespace psxrl::rl;

namespace {

struct Run {
  Env env;
  std::uint64_t seed = 1;
  std::uint32_t lcg = 7;
  psx::Cycles cycles = 0;  // emulated in moves, resets left out
  std::uint64_t instructions = 0;  // the CPU's count in moves (skipped idle loops' included)
  Run(const EnvConfig& c, std::ostream* code_map) : env(c) {
    env.console().set_code_map(code_map);  // before the first frame compiles anything
    env.reset(1, seed, nullptr);
  }
};

void play(Run& run, int moves) {
  for (int i = 0; i < moves; ++i) {
    const psx::Cycles before = run.env.console().cycles();
    const std::uint64_t executed = run.env.console().instructions();
    auto r = run.env.step(bench::action_at(run.lcg));
    run.cycles += run.env.console().cycles() - before;
    run.instructions += run.env.console().instructions() - executed;
    if (r.terminated || r.truncated) run.env.reset(1, ++run.seed, nullptr);
  }
}

// Separate from the warm-up, so that a profiler can be told to count this function alone.
[[gnu::noinline]] void measured_moves(Run& run, int moves) { play(run, moves); }

}  // namespace

int main(int argc, char** argv) {
  const bool perf_map = argc > 1 && std::strcmp(argv[argc - 1], "--perf-map") == 0;
  if (perf_map) --argc;
  const int warmup = argc > 1 ? std::atoi(argv[1]) : 200;
  const int moves = argc > 2 ? std::atoi(argv[2]) : 100;
  EnvConfig c;
  c.obs = argc > 3 ? argv[3] : "simple";
  // Where perf looks for the names of code it finds no symbols for.
  std::ofstream map;
  if (perf_map) map.open("/tmp/perf-" + std::to_string(getpid()) + ".map");
  Run run(c, perf_map ? &map : nullptr);
  play(run, warmup);
  run.cycles = run.instructions = 0;
  const psx::IdleSkip::Stats idle0 = run.env.console().idle_skip_stats();
  const auto t = bench::Clock::now();
  measured_moves(run, moves);
  const double seconds = bench::seconds_since(t);
  const psx::IdleSkip::Stats& idle = run.env.console().idle_skip_stats();
  const auto ram = std::as_const(run.env.console()).ram();
  std::printf("Tumble level 1, obs %s: %d moves after %d warm-up, %.3f s (%.1f moves/s)\n", c.obs.c_str(), moves,
              warmup, seconds, moves / seconds);
  std::printf("cycles per move %.1f, instructions per move %.1f, RAM hash %016llx\n",
              static_cast<double>(run.cycles) / moves, static_cast<double>(run.instructions) / moves,
              static_cast<unsigned long long>(psx::fnv1a(ram.data(), ram.size())));
  const auto per_move = [moves](std::uint64_t now, std::uint64_t before) {
    return static_cast<double>(now - before) / moves;
  };
  const auto& rec = run.env.console().recompiler_stats();
  std::printf("recompiler: %llu blocks compiled, %llu invalidations, %llu code-buffer flushes (warm-up included)\n",
              static_cast<unsigned long long>(rec.compiled), static_cast<unsigned long long>(rec.invalidated),
              static_cast<unsigned long long>(rec.flushes));
  std::printf("idle skipping per move: %.1f cycles in %.1f skips (%.1f made from the head, %.1f proofs), "
              "%.1f visits left unexamined\n",
              per_move(idle.cycles, idle0.cycles), per_move(idle.skips, idle0.skips),
              per_move(idle.repeats, idle0.repeats), per_move(idle.proofs, idle0.proofs),
              per_move(idle.unexamined, idle0.unexamined));
  return 0;
}
