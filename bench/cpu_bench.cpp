// CPU interpreter throughput: runs a CPU-bound PlayStation program (bench/roms/cpu_loop.c) for a
// fixed number of emulated frames and prints emulated instructions per host second.
#include <chrono>
#include <cstdio>
#include <string>

#include "core/console.h"

int main(int argc, char** argv) {
  std::string exe = argc > 1 ? argv[1] : PSXRL_BUILD_DIR "/bench/cpu_loop.exe";
  int frames = argc > 2 ? std::stoi(argv[2]) : 600;
  psx::Console console;
  console.boot_exe(exe);
  auto t0 = std::chrono::steady_clock::now();
  console.run_frames(frames);
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double ips = console.instructions() / s;
  std::printf("cpu_bench: %d frames, %llu instructions, %llu cycles in %.3f s\n", frames,
              static_cast<unsigned long long>(console.instructions()),
              static_cast<unsigned long long>(console.cycles()), s);
  std::printf("cpu_bench: %.1f million emulated instructions per second, %.1fx real time\n", ips / 1e6,
              console.cycles() / s / psx::kCpuClockHz);
  return 0;
}
