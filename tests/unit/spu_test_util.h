// Shared helpers for the SPU unit tests: a standalone SPU on its own scheduler, register
// access by psx-spx address, and running whole 44.1 kHz samples.
#pragma once
#include <vector>

#include "core/audio_fifo.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "spu/spu.h"

namespace psx::test {

struct SpuRig {
  Scheduler sched;
  InterruptController irq;
  AudioFifo cd;
  Spu spu{sched, irq, cd};

  // `addr` is the full I/O address (1F801xxxh), as in psx-spx.
  void w16(u32 addr, u16 v) { spu.io_write(addr - Spu::kBase, v, 2); }
  u16 r16(u32 addr) { return static_cast<u16>(spu.io_read(addr - Spu::kBase, 2)); }
  void voice_w(u32 v, u32 reg, u16 value) { w16(0x1F801C00 + v * 0x10 + reg, value); }
  u16 voice_r(u32 v, u32 reg) { return r16(0x1F801C00 + v * 0x10 + reg); }

  void run_samples(u32 n) {
    for (u32 i = 0; i < n; ++i) {
      sched.advance(Spu::kCyclesPerSample);
      sched.run_due_events();
    }
  }
  std::vector<StereoSample> take() {
    std::vector<StereoSample> out;
    spu.take_samples(out);
    return out;
  }
  void put_ram(u32 byte_addr, const std::vector<u8>& bytes) {
    for (size_t i = 0; i < bytes.size(); ++i) spu.ram()[(byte_addr + i) & (Spu::kRamSize - 1)] = bytes[i];
  }
};

}  // namespace psx::test
