// Environment throughput on Tumble level 1: moves per second for one environment and for the
// vector environment at 1 and 2 threads, per observation kind, and host memory per environment
// (resident set growth divided by the number of environments). Actions follow a fixed sequence;
// episodes that end are reset, as in training.
#include <cstdio>
#include <memory>
#include <vector>

#include "bench_util.h"

using namespace psxrl::rl;
using bench::resident_kib;
using bench::single_moves_per_second;
using bench::vec_moves_per_second;

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
