// Renderer benchmark: Tumble's emulated frames per second with the software renderer and with the
// OpenGL renderer on OSMesa (llvmpipe, headless) at scales 1, 2 and 4, on the title and on level
// 1 in play (the same workloads as psxrl_bench). Each run includes the per-frame picture for the
// host (at the renderer's scale), as psxrl run/play produce it. Prints a Markdown table, then
// the figures as JSON. The host clock is used only to time the runs; on a shared machine the
// figures vary with its load, printed with them.
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

#include "bench_util.h"
#include "core/console.h"
#include "gpu/gl/gl_renderer.h"
#include "gpu/gl/osmesa_context.h"

namespace {

using bench::Clock;
using bench::seconds_since;

const std::string kTumble = PSXRL_BUILD_DIR "/games/tumble/tumble.exe";
constexpr psx::u32 kRequestLevel = 0x80010048;  // Tumble's RAM contract (games/tumble/README.md)

// Frames per second over `frames` frames; scale 0 is the software renderer. -1 when OpenGL is
// unavailable (the reason is printed).
double fps(bool level, psx::u32 scale, int frames) {
  psx::Console c;
  if (scale) {
    std::string error;
    auto r = psx::gpu::gl::make_osmesa_renderer(scale, psx::gpu::gl::OsMesaContext::kDefaultLibrary, error);
    if (!r) {
      std::fprintf(stderr, "renderer_bench: no OpenGL renderer: %s\n", error.c_str());
      return -1;
    }
    c.set_renderer(std::move(r));
  }
  c.boot_exe(kTumble);
  c.run_frames(200);
  if (level) {
    c.write32(kRequestLevel, 1);
    c.run_frames(20);
  }
  auto t = Clock::now();
  for (int f = 0; f < frames; ++f) {
    if (level && f % 40 == 0) c.press_for(1, f % 120 ? psx::pad_button::kUp : psx::pad_button::kRight, 3);
    c.run_frame();
  }
  return frames / seconds_since(t);
}

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string one, five, fifteen;
  f >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

}  // namespace

int main() {
  std::printf("# psxrl renderer benchmark (Tumble, 300 frames each)\n\nload average before: %s\n\n",
              load_average().c_str());
  std::printf("| renderer | title frames/s | level 1 frames/s |\n| --- | --- | --- |\n");
  std::string json;
  for (psx::u32 scale : {0u, 1u, 2u, 4u}) {
    const double title = fps(false, scale, 300), level = fps(true, scale, 300);
    const std::string name = scale ? "OpenGL (OSMesa) scale " + std::to_string(scale) : "software";
    std::printf("| %s | %.1f | %.1f |\n", name.c_str(), title, level);
    const std::string key = scale ? "gl_scale" + std::to_string(scale) : "software";
    char item[160];
    std::snprintf(item, sizeof item, "%s  \"%s_title_fps\": %.4g,\n  \"%s_level_fps\": %.4g", json.empty() ? "" : ",\n",
                  key.c_str(), title, key.c_str(), level);
    json += item;
  }
  std::printf("\nload average after: %s\n\n{\n%s\n}\n", load_average().c_str(), json.c_str());
  return 0;
}
