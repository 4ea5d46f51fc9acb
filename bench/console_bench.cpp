// Console API costs: save and load time and state size (raw and compressed), and the frame-time
// cost of memory watches (none vs ten, placed on the pages the workload writes).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "core/console.h"

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

const std::string kExe = PSXRL_BUILD_DIR "/bench/cpu_loop.exe";

const std::string kGame = PSXRL_BUILD_DIR "/games/tumble/tumble.exe";

// Tumble playing level 1 (started through its request variable, rolling forward and turning),
// with `watches` watches on its RAM contract fields (games/tumble/README.md): the typical RL use.
double game_frame_ms(int watches, int frames) {
  psx::Console c;
  c.boot_exe(kGame);
  c.run_frames(60);
  c.write32(0x80010000 + 0x48, 1);  // request_level = 1 (README "RAM contract")
  static const psx::u32 kFields[10] = {0x08, 0x0C, 0x10, 0x14, 0x18, 0x1C, 0x20, 0x24, 0x28, 0x2C};
  for (int i = 0; i < watches; ++i) c.watch("f" + std::to_string(i), 0x80010000 + kFields[i], 4);
  auto t = Clock::now();
  for (int f = 0; f < frames; ++f) {
    if (f % 40 == 0) c.press_for(1, f % 120 ? psx::pad_button::kUp : psx::pad_button::kRight, 3);
    c.run_frame();
  }
  double ms = seconds_since(t) * 1000 / frames;
  std::printf("  Tumble, %2d watches: %.3f ms per frame (%zu events)\n", watches, ms, c.take_watch_events().size());
  return ms;
}

double frame_ms(int watches, int frames) {
  psx::Console c;
  c.boot_exe(kExe);
  c.run_frames(10);
  // The workload's buffers sit in its BSS after the code at 0x80010000: watch words there.
  for (int i = 0; i < watches; ++i) c.watch("w" + std::to_string(i), 0x80011000 + 0x800 * i, 4);
  auto t = Clock::now();
  c.run_frames(frames);
  double ms = seconds_since(t) * 1000 / frames;
  std::printf("  %2d watches: %.3f ms per frame (%zu events)\n", watches, ms, c.take_watch_events().size());
  return ms;
}

}  // namespace

int main() {
  psx::Console c;
  c.boot_exe(kExe);
  c.run_frames(30);
  for (bool compress : {false, true}) {
    const int n = 50;
    std::vector<psx::u8> blob;
    auto t = Clock::now();
    for (int i = 0; i < n; ++i) blob = c.save_state(compress);
    double save = seconds_since(t) / n;
    t = Clock::now();
    for (int i = 0; i < n; ++i) c.load_state(blob);
    double load = seconds_since(t) / n;
    std::printf("console_bench: save state %s: %zu bytes, save %.3f ms, load %.3f ms\n",
                compress ? "compressed" : "raw", blob.size(), save * 1000, load * 1000);
  }
  // The machine may be shared: alternate the two set-ups and keep each one's best run.
  std::printf("console_bench: memory watch cost (best of 3 alternating runs)\n");
  double base = 1e9, ten = 1e9;
  for (int round = 0; round < 3; ++round) {
    base = std::min(base, frame_ms(0, 300));
    ten = std::min(ten, frame_ms(10, 300));
  }
  std::printf("console_bench: ten watches on constantly written pages cost %+.1f%% frame time\n",
              (ten / base - 1) * 100);
  base = ten = 1e9;
  for (int round = 0; round < 3; ++round) {
    base = std::min(base, game_frame_ms(0, 600));
    ten = std::min(ten, game_frame_ms(10, 600));
  }
  std::printf("console_bench: ten watches on Tumble's variables cost %+.1f%% frame time\n", (ten / base - 1) * 100);
  return 0;
}
