// Shared fixture for the GPU unit tests: a Gpu on its own scheduler, driven with GP0/GP1 words
// exactly as the CPU would write them, with VRAM inspected directly.
#pragma once
#include <gtest/gtest.h>

#include <initializer_list>

#include "core/irq.h"
#include "core/scheduler.h"
#include "gpu/gpu.h"

namespace psx::test {

class GpuTest : public ::testing::Test {
 protected:
  GpuTest() : gpu(sched, irq) {
    gp1(0x00000000);
    gp0({0xE3000000, 0xE4000000 | (511u << 10) | 1023u});  // drawing area: all of VRAM
  }

  void gp0(std::initializer_list<u32> words) {
    for (u32 w : words) gpu.io_write(0, w, 4);
  }
  void gp1(u32 word) { gpu.io_write(4, word, 4); }
  u32 stat() { return gpu.io_read(4, 4); }
  u16 px(u32 x, u32 y) const { return gpu.vram()[y * 1024 + x]; }
  // Writes one VRAM pixel through a 1x1 GP0(A0) transfer.
  void poke(u32 x, u32 y, u16 v) { gp0({0xA0000000, (y << 16) | x, 0x00010001, v}); }
  // Fills a rectangle through GP0(A0) with one value (any size, no 16-pixel rounding).
  void poke_rect(u32 x, u32 y, u32 w, u32 h, u16 v) {
    gp0({0xA0000000, (y << 16) | x, (h << 16) | w});
    u32 n = w * h;
    for (u32 i = 0; i < n; i += 2) gp0({u32{v} | (u32{v} << 16)});
  }
  // Runs the scheduler forward by `cycles` CPU cycles, dispatching events on time.
  void run(Cycles cycles) {
    Cycles end = sched.now() + cycles;
    while (sched.now() < end) {
      Cycles next = std::min(sched.next_deadline(), end);
      sched.advance(next - sched.now());
      sched.run_due_events();
    }
  }

  static constexpr u32 rgb15(u32 r, u32 g, u32 b) { return r | (g << 5) | (b << 10); }
  static constexpr u32 xy(s32 x, s32 y) { return (static_cast<u32>(y) << 16) | (static_cast<u32>(x) & 0xFFFF); }

  Scheduler sched;
  InterruptController irq;
  Gpu gpu;
};

}  // namespace psx::test
