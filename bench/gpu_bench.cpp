// GPU benchmark: drives psx::Gpu with GP0 words directly (no CPU) and prints
//  1. frames/s for a heavy scene: 2000 textured (4-bit CLUT), Gouraud-shaded, dithered triangles
//     per frame inside a 320x240 drawing area, plus the frame's clear (fill rectangle);
//  2. rasterised pixels/s for full-screen quads (exact pixel count 320x240 per quad) in the
//     common modes: flat, Gouraud, textured raw, textured Gouraud, semi-transparent textured.
// The host clock is used here only to time the runs.
#include <chrono>
#include <cstdio>
#include <vector>

#include "core/irq.h"
#include "core/scheduler.h"
#include "gpu/gpu.h"

namespace {

using psx::u32;

u32 xy(int x, int y) { return (static_cast<u32>(y) << 16) | (static_cast<u32>(x) & 0xFFFF); }

struct Lcg {  // deterministic scene generator
  u32 s = 12345;
  u32 next(u32 n) {
    s = s * 1664525u + 1013904223u;
    return (s >> 8) % n;
  }
};

void setup(psx::Gpu& gpu) {
  gpu.gp1_write(0x00000000);
  gpu.gp0_write(0xE3000000);
  gpu.gp0_write(0xE4000000 | (239u << 10) | 319u);
  // A 4-bit texture page at (640,0) with varied texels and a CLUT at (0,480).
  gpu.gp0_write(0xA0000000);
  gpu.gp0_write(xy(640, 0));
  gpu.gp0_write(xy(64, 256));
  Lcg r;
  for (u32 i = 0; i < 64 * 256 / 2; ++i) gpu.gp0_write(r.s = r.s * 1103515245u + 12345u);
  gpu.gp0_write(0xA0000000);
  gpu.gp0_write(xy(0, 480));
  gpu.gp0_write(xy(16, 1));
  for (u32 i = 0; i < 8; ++i) gpu.gp0_write(0x7FFF0000u + i * 0x04210421u + 1);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void heavy_scene(psx::Gpu& gpu) {
  constexpr int kTriangles = 2000, kFrames = 300;
  const u32 clut = (0 / 16) | (480u << 6), page = 10 | (0 << 7) | (1 << 9);
  // Pre-generate the command words (what a game's ordering table would hold).
  std::vector<u32> words;
  Lcg r;
  for (int t = 0; t < kTriangles; ++t) {
    int x = static_cast<int>(r.next(300)), y = static_cast<int>(r.next(220));
    for (int k = 0; k < 3; ++k) {
      u32 colour = 0x404040 + r.next(0x808080) ;
      if (k == 0) words.push_back(0x34000000 | (colour & 0xFFFFFF));
      else words.push_back(colour & 0xFFFFFF);
      words.push_back(xy(x + static_cast<int>(r.next(40)) - 10, y + static_cast<int>(r.next(40)) - 10));
      u32 attr = k == 0 ? clut : k == 1 ? page : 0;
      words.push_back((attr << 16) | (r.next(256) << 8) | r.next(256));
    }
  }
  auto t0 = std::chrono::steady_clock::now();
  for (int f = 0; f < kFrames; ++f) {
    gpu.gp0_write(0x02000000);
    gpu.gp0_write(0);
    gpu.gp0_write(xy(320, 240));
    gpu.dma_write(words.data(), static_cast<u32>(words.size()));
  }
  double s = seconds_since(t0);
  std::printf("heavy scene: %d textured Gouraud triangles/frame at 320x240: %.1f frames/s (%.2f ms/frame)\n",
              kTriangles, kFrames / s, 1000.0 * s / kFrames);
}

void fill_rate(psx::Gpu& gpu, const char* name, u32 command, bool textured, bool shaded) {
  constexpr int kQuads = 400;
  const int xs[4] = {0, 320, 0, 320}, ys[4] = {0, 0, 240, 240};
  const u32 clut = 480u << 6, page = 10 | (1 << 9);
  std::vector<u32> words;
  for (int k = 0; k < 4; ++k) {
    u32 colour = 0x303030 + 0x202020 * static_cast<u32>(k);
    if (k == 0) words.push_back(command | colour);
    else if (shaded) words.push_back(colour);
    words.push_back(xy(xs[k], ys[k]));
    if (textured) words.push_back(((k == 0 ? clut : k == 1 ? page : 0) << 16) | (ys[k] / 2 << 8) | xs[k] / 2);
  }
  auto t0 = std::chrono::steady_clock::now();
  for (int q = 0; q < kQuads; ++q) gpu.dma_write(words.data(), static_cast<u32>(words.size()));
  double s = seconds_since(t0);
  double pixels = 320.0 * 240.0 * kQuads;
  std::printf("fill rate %-34s %7.1f Mpixels/s\n", name, pixels / s / 1e6);
}

}  // namespace

int main() {
  psx::Scheduler sched;
  psx::InterruptController irq;
  psx::Gpu gpu(sched, irq);
  setup(gpu);
  heavy_scene(gpu);
  fill_rate(gpu, "flat untextured quad:", 0x28000000, false, false);
  fill_rate(gpu, "Gouraud quad (dithered):", 0x38000000, false, true);
  fill_rate(gpu, "textured raw quad (4-bit CLUT):", 0x2D000000, true, false);
  fill_rate(gpu, "textured Gouraud quad (dithered):", 0x3C000000, true, true);
  fill_rate(gpu, "semi-transparent textured Gouraud:", 0x3E000000, true, true);
  return 0;
}
