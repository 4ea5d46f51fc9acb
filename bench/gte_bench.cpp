// GTE benchmark: commands per second for the mix a 3D game issues per triangle
// (RTPT to transform and project 3 vertices, NCDT to light them, AVSZ3 for the ordering-table Z).
#include <chrono>
#include <cstdio>

#include "core/gte/gte.h"

int main() {
  using psx::u32;
  psx::Gte gte;
  // A camera rotated about Y by ~30 degrees (cos=0DDBh, sin=0800h in 4.12), pushed back 2000.
  gte.write_control(0, 0x0DDB);              // RT11, RT12=0
  gte.write_control(1, 0x00000800);          // RT13, RT21=0
  gte.write_control(2, 0x00001000);          // RT22, RT23=0
  gte.write_control(3, u32(-0x800) & 0xFFFF);  // RT31, RT32=0
  gte.write_control(4, 0x0DDB);              // RT33
  gte.write_control(7, 2000);                // TRZ
  gte.write_control(8, 0x0800'0800);         // LLM row 1
  gte.write_control(12, 0x0800);
  gte.write_control(16, 0x0000'1000);        // LCM: white light
  gte.write_control(18, 0x0000'1000);
  gte.write_control(20, 0x1000);
  gte.write_control(13, 0x200);              // BK
  gte.write_control(21, 0x800);              // FC
  gte.write_control(24, 160u << 16);         // OFX
  gte.write_control(25, 120u << 16);         // OFY
  gte.write_control(26, 300);                // H
  gte.write_control(27, u32(-0x100));        // DQA
  gte.write_control(28, 0x1400000);          // DQB
  gte.write_control(29, 0x555);              // ZSF3
  gte.write_data(6, 0x30808080);             // RGBC

  constexpr u32 kSf = 1u << 19, kLm = 1u << 10;
  constexpr u32 kRtpt = 0x30 | kSf, kNcdt = 0x16 | kSf | kLm, kAvsz3 = 0x2D;
  constexpr int kTriangles = 2'000'000;
  u32 checksum = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int t = 0; t < kTriangles; ++t) {
    const u32 x = u32(t & 0x3FF), y = u32((t >> 3) & 0x3FF);
    gte.write_data(0, (y << 16) | x);
    gte.write_data(1, u32(t & 0x1FF));
    gte.write_data(2, ((y + 64) << 16) | x);
    gte.write_data(3, 100);
    gte.write_data(4, (y << 16) | (x + 64));
    gte.write_data(5, 200);
    gte.execute(kRtpt);
    gte.execute(kAvsz3);
    checksum += gte.read_data(7) + gte.read_data(14);
    gte.execute(kNcdt);
    checksum += gte.read_data(22);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double commands = 3.0 * kTriangles;
  std::printf("gte_bench: %d x (RTPT, AVSZ3, NCDT) = %.0f commands in %.3f s\n", kTriangles, commands, seconds);
  std::printf("gte_bench: %.2f million commands/s (%.2f million triangles/s), checksum %08x\n",
              commands / seconds / 1e6, kTriangles / seconds / 1e6, checksum);
  return 0;
}
