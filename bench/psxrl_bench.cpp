// psxrl's one-command benchmark: the machine, then emulation speed (emulated frames per second
// and multiple of real time) on a CPU-bound program, a GTE/GPU-bound program, a VSync-bound cube
// and Tumble (title and in play; the last three with idle skipping on and off), each with the
// interpreter and the recompiler, environment moves per second per observation kind,
// vector-environment scaling over threads (batched and asynchronous), host memory per console,
// save-state and snapshot times and the environment's reset time. Prints Markdown tables, then
// the same figures as JSON. The host clock is used only to time the runs; on a shared machine
// figures vary with its load, which is printed with them.
#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bench_util.h"
#include "core/console.h"

namespace {

using bench::Clock;
using bench::seconds_since;
using psx::Console;

std::string cpu_model() {
  std::ifstream f("/proc/cpuinfo");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string one, five, fifteen;
  f >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

// JSON members collected as the figures are measured.
struct Json {
  std::vector<std::string> items;
  void add(const std::string& key, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    items.push_back("\"" + key + "\": " + buf);
  }
  void add(const std::string& key, const std::string& v) { items.push_back("\"" + key + "\": \"" + v + "\""); }
  void print() const {
    std::printf("{\n");
    for (size_t i = 0; i < items.size(); ++i) std::printf("  %s%s\n", items[i].c_str(), i + 1 < items.size() ? "," : "");
    std::printf("}\n");
  }
};

const std::string kTumble = PSXRL_BUILD_DIR "/games/tumble/tumble.exe";
constexpr psx::u32 kRequestLevel = 0x80010048;  // Tumble's RAM contract (games/tumble/README.md)

struct Workload {
  const char* key;
  const char* name;
  std::string exe;
  bool level;      // Tumble: start level 1 and play (moves every 40 frames)
  int warm_frames;
  int frames;      // timed
  bool waits;      // waits for VBlank: also measured with idle skipping off
};

// Emulated frames per second and multiple of real time over `frames` frames after warming up,
// with the interpreter or the recompiler (which compute the same frames, only at another speed).
void measure(const Workload& w, Console::CpuMode cpu, bool skip, int frames, Json& json) {
  const bool rec = cpu == Console::CpuMode::Recompiler;
  Console c;
  c.set_cpu_mode(cpu);
  c.set_idle_skip(skip);
  c.boot_exe(w.exe);
  c.run_frames(w.warm_frames);
  if (w.level) {
    c.write32(kRequestLevel, 1);
    c.run_frames(20);
  }
  const psx::Cycles c0 = c.cycles();
  auto t = Clock::now();
  for (int f = 0; f < frames; ++f) {
    if (w.level && f % 40 == 0) c.press_for(1, f % 120 ? psx::pad_button::kUp : psx::pad_button::kRight, 3);
    c.run_frame();
  }
  const double s = seconds_since(t);
  const double fps = frames / s, realtime = double(c.cycles() - c0) / s / psx::kCpuClockHz;
  std::printf("| %s | %s | %s | %.1f | %.2fx |\n", w.name, rec ? "recompiler" : "interpreter", skip ? "on" : "off",
              fps, realtime);
  const std::string key = std::string(w.key) + (skip ? "" : "_no_idle_skip") + (rec ? "_recompiler" : "");
  json.add(key + "_fps", fps);
  json.add(key + "_realtime", realtime);
}

void emulation(Json& json) {
  const std::vector<Workload> loads = {
      {"cpu_loop", "CPU-bound (bench/roms/cpu_loop.c)", PSXRL_BUILD_DIR "/bench/cpu_loop.exe", false, 10, 300, false},
      {"gte_gpu_loop", "GTE/GPU-bound (bench/roms/gte_gpu_loop.c)", PSXRL_BUILD_DIR "/bench/gte_gpu_loop.exe", false, 10,
       300, false},
      {"vsync_cube", "VSync-bound cube (bench/roms/vsync_cube.c)", PSXRL_BUILD_DIR "/bench/vsync_cube.exe", false, 10,
       3000, true},
      {"tumble_title", "Tumble, title", kTumble, false, 200, 300, true},
      {"tumble_level", "Tumble, level 1 in play", kTumble, true, 200, 300, true},
  };
  std::printf("\n## Emulation\n\n| workload | cpu | idle skip | frames/s | real time |\n| --- | --- | --- | --- | --- |\n");
  for (const Workload& w : loads) {
    for (Console::CpuMode cpu : {Console::CpuMode::Interpreter, Console::CpuMode::Recompiler}) {
      measure(w, cpu, true, w.frames, json);
      if (w.waits) measure(w, cpu, false, std::min(w.frames, 300), json);
    }
  }
}

void environments(Json& json) {
  std::printf("\n## Environment (Tumble level 1, fixed pseudo-random moves, 100 timed after 100 of warm-up)\n\n| observation | moves/s |\n| --- | --- |\n");
  for (const char* obs : {"simple", "local", "episode", "ram", "visual", "audio", "multimodal"}) {
    const double mps = bench::single_moves_per_second(obs, 100, 100);
    std::printf("| %s | %.1f |\n", obs, mps);
    json.add(std::string("env_") + obs + "_moves_per_s", mps);
  }
  // 16 environments whatever the thread count, so every row does the same moves; threads beyond
  // the machine's hardware threads share them (their efficiency shows the machine, not the pool).
  std::printf("\n## Vector environment (16 environments, simple, 8 steps timed after 8)\n\n| threads | moves/s | speed-up | efficiency per thread |\n"
              "| --- | --- | --- | --- |\n");
  double one = 0;
  for (unsigned threads : {1u, 2u, 4u, 8u, 16u}) {
    const double mps = bench::vec_moves_per_second("simple", 16, threads, 8, 8);
    if (threads == 1) one = mps;
    std::printf("| %u | %.1f | %.2fx | %.0f%% |\n", threads, mps, mps / one, 100 * mps / one / threads);
    json.add("vec_env_" + std::to_string(threads) + "_threads_moves_per_s", mps);
  }
  // Asynchronous stepping as EnvPool recommends: twice as many environments as threads, batches
  // of one environment per thread, so a thread never waits for another's longer move.
  std::printf("\n## Asynchronous vector environment (2 environments per thread, batch = threads, simple, 16 moves per environment timed after 16)\n\n"
              "| threads | environments | moves/s | speed-up | efficiency per thread |\n| --- | --- | --- | --- | --- |\n");
  for (unsigned threads : {1u, 2u, 4u, 8u, 16u}) {
    const int envs = static_cast<int>(2 * threads);
    const double mps = bench::async_moves_per_second("simple", envs, static_cast<int>(threads), threads, 16 * envs,
                                                       16 * envs);
    if (threads == 1) one = mps;
    std::printf("| %u | %d | %.1f | %.2fx | %.0f%% |\n", threads, envs, mps, mps / one, 100 * mps / one / threads);
    json.add("async_env_" + std::to_string(threads) + "_threads_moves_per_s", mps);
  }
}

// Resident memory per console: 8 consoles booted into Tumble's title, on the recompiler as the
// environments run them (its code buffer is the difference from the interpreter).
void memory(Json& json) {
  // Earlier sections freed their consoles, and malloc keeps freed pages for reuse: without handing
  // them back first, the new consoles would fit in them and resident memory would not grow at all.
  malloc_trim(0);
  const long before = bench::resident_kib();
  std::vector<std::unique_ptr<Console>> consoles;
  for (int i = 0; i < 8; ++i) {
    consoles.push_back(std::make_unique<Console>());
    consoles.back()->set_cpu_mode(Console::CpuMode::Recompiler);
    consoles.back()->boot_exe(kTumble);
    consoles.back()->run_frames(60);
  }
  const double mib = double(bench::resident_kib() - before) / 1024 / 8;
  std::printf("\n## Costs\n\n| what | figure |\n| --- | --- |\n| host memory per console (Tumble, recompiler) | %.1f MiB |\n", mib);
  json.add("memory_per_console_mib", mib);
  // An environment's console as training runs it, after 300 moves of level 1: the code buffer grows
  // with the code a game runs (the title compiles little, play much more), and drawing nobody
  // looks at waits in the GPU's draw log and queue.
  malloc_trim(0);
  const long envs_before = bench::resident_kib();
  std::vector<std::unique_ptr<psxrl::rl::Env>> envs;
  for (int e = 0; e < 4; ++e) {
    auto& env = envs.emplace_back(std::make_unique<psxrl::rl::Env>(psxrl::rl::EnvConfig{}));
    env->reset(1, 1, nullptr);
    std::uint32_t lcg = 7;
    for (int i = 0; i < 300; ++i) {
      const auto r = env->step(bench::action_at(lcg));
      if (r.terminated || r.truncated) env->reset(1, 2 + i, nullptr);
    }
  }
  const double env_mib = double(bench::resident_kib() - envs_before) / 1024 / 4;
  const double code = double(envs[0]->console().recompiler_code_bytes()) / (1 << 20);
  std::printf("| host memory per environment after 300 moves of Tumble level 1 (4 of them; code and draw log included) | %.1f MiB |\n", env_mib);
  std::printf("| compiled code held by a console after 300 moves of Tumble level 1 (the first row compiles only the title) | %.1f MiB |\n", code);
  json.add("memory_per_env_after_300_moves_mib", env_mib);
  json.add("compiled_code_after_300_moves_mib", code);
}

double mean_ms(int n, const std::function<void()>& f) {
  auto t = Clock::now();
  for (int i = 0; i < n; ++i) f();
  return seconds_since(t) * 1000 / n;
}

void states(Json& json) {
  Console c;
  c.boot_exe(kTumble);
  c.run_frames(200);
  std::vector<psx::u8> blob;
  const double save = mean_ms(20, [&] { blob = c.save_state(false); });
  const double load = mean_ms(20, [&] { c.load_state(blob); });
  Console::Snapshot snap;
  const double take = mean_ms(50, [&] { c.snapshot(snap); });
  const double restore = mean_ms(200, [&] { c.restore(snap); });
  psxrl::rl::EnvConfig config;
  config.obs = "simple";
  psxrl::rl::Env env(config);
  std::uint64_t seed = 0;
  const double reset = mean_ms(20, [&] { env.reset(1, ++seed); });
  const psxrl::rl::Env::Snapshot start = env.snapshot();
  const double reset_to = mean_ms(200, [&] { env.reset_to(start, ++seed); });
  std::printf("| save state (uncompressed, %.1f MiB) | %.3f ms |\n| load state | %.3f ms |\n", blob.size() / 1048576.0,
              save, load);
  std::printf("| snapshot (in memory) | %.3f ms |\n| restore snapshot | %.3f ms |\n", take, restore);
  std::printf("| environment reset (restore, then the frames that start the level) | %.3f ms |\n", reset);
  std::printf("| environment reset to an in-memory snapshot (Env::reset_to) | %.3f ms |\n", reset_to);
  json.add("save_state_ms", save);
  json.add("load_state_ms", load);
  json.add("snapshot_ms", take);
  json.add("restore_ms", restore);
  json.add("env_reset_ms", reset);
  json.add("env_reset_to_snapshot_ms", reset_to);
}

}  // namespace

int main() {
  Json json;
  const std::string model = cpu_model(), load = load_average();
  const unsigned cores = std::thread::hardware_concurrency();
  std::printf("# psxrl benchmark\n\nMachine: %s, %u hardware threads; load average at start %s\n", model.c_str(), cores,
              load.c_str());
  json.add("cpu", model);
  json.add("hardware_threads", cores);
  json.add("load_average_start", load);
  emulation(json);
  environments(json);
  memory(json);
  states(json);
  const std::string end_load = load_average();
  std::printf("\nLoad average at end: %s\n\n```json\n", end_load.c_str());
  json.add("load_average_end", end_load);
  json.print();
  std::printf("```\n");
  return 0;
}
