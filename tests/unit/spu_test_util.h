// Shared helpers for the SPU unit tests: a standalone SPU on its own scheduler, register
// access by psx-spx address, and running whole 44.1 kHz samples.
#pragma once
#include <array>
#include <functional>
#include <vector>

#include "core/audio_fifo.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "core/state.h"
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

// A fixed pseudo-random sequence (the same in every rig of a comparison).
struct Lcg {
  u32 x;
  u32 next(u32 n) {
    x = x * 1664525u + 1013904223u;
    return (x >> 8) % n;
  }
};

// The rig of the randomised workloads that compare batch sizes (spu_lazy_test,
// spu_silent_test): a standalone SPU driven like the CPU drives it, recording what can be seen
// of it - register reads, IRQ9 edges (noted with their time and acknowledged at once), output
// samples and the state bytes.
struct SpuTrace {
  Scheduler sched;
  InterruptController irq;
  AudioFifo cd;
  // An event registered before the SPU's, so that it wins a tie with a sample (the lower handle
  // runs first); it calls before_spu_event, which a workload sets if it books the event.
  std::function<void(Cycles)> before_spu_event;
  Scheduler::Handle before_spu = sched.add_event("trace.before_spu", [this](Cycles late) { before_spu_event(late); });
  Spu spu{sched, irq, cd};
  u16 attr = 0;  // the last ATTR written
  std::vector<Cycles> irq_times;
  std::vector<u32> reads;
  std::vector<StereoSample> out;  // every output sample taken so far

  static constexpr u32 kAttr = 0x1F801DAA;

  void note_irq() {
    if (irq.stat() & (1u << static_cast<u32>(Irq::Spu))) {
      irq_times.push_back(sched.now());
      irq.write(0x0, ~(1u << static_cast<u32>(Irq::Spu)));  // acknowledge I_STAT bit 9
    }
  }
  // Like the CPU: time moves in steps of step() cycles (instruction-sized, now and then a long
  // stall in some workloads); due events run between steps.
  template <class Step>
  void run_for(Cycles n, Step step) {
    const Cycles end = sched.now() + n;
    while (sched.now() < end) {
      sched.advance(step());
      if (sched.now() >= sched.next_deadline()) {
        sched.run_due_events();
        note_irq();
      }
    }
  }
  void w16(u32 addr, u16 v) {
    if (addr == kAttr) attr = v;
    spu.io_write(addr - Spu::kBase, v, 2);
    note_irq();
  }
  u16 r16(u32 addr) {
    const u16 v = static_cast<u16>(spu.io_read(addr - Spu::kBase, 2));
    reads.push_back(v);
    note_irq();
    return v;
  }
  void voice_w(u32 v, u32 reg, u16 value) { w16(0x1F801C00 + v * 0x10 + reg, value); }
  std::vector<u8> state() {
    StateIO w;
    spu.do_state(w);
    return w.buffer();
  }
  void take() {
    std::vector<StereoSample> v;
    spu.take_samples(v);
    out.insert(out.end(), v.begin(), v.end());
  }
};

// The mix and reverb setup the register-driven workloads share (spu_on_demand_test,
// spu_lazy_test): main volume MVOL 3FFFh, reverb output EVOL 3000h, CD input AVOL 4000h, and the
// 32 reverb registers at 1F801DC0h (psx-spx "SPU Reverb Registers", dAPF1..vRIN) with short
// delays, so that a small work area is read and written on every reverb tick.
inline constexpr std::array<u16, 32> kTestReverbRegs = {
    0x0040, 0x0030, 0x7000, 0x4000, 0xD000, 0x3000, 0xE000, 0x6000, 0x5000, 0xB000, 0x0100,
    0x00F0, 0x00E0, 0x00D0, 0x00C0, 0x00B0, 0x0180, 0x0170, 0x0160, 0x0150, 0x00A0, 0x0090,
    0x0080, 0x0078, 0x01F0, 0x01E0, 0x0070, 0x0068, 0x0050, 0x0048, 0x6000, 0x6000};
template <class Rig>
void write_test_volumes_and_reverb(Rig& r) {
  r.w16(0x1F801D80, 0x3FFF);  // MVOLL/MVOLR
  r.w16(0x1F801D82, 0x3FFF);
  r.w16(0x1F801D84, 0x3000);  // EVOLL/EVOLR
  r.w16(0x1F801D86, 0x3000);
  r.w16(0x1F801DB0, 0x4000);  // AVOLL/AVOLR: CD input
  r.w16(0x1F801DB2, 0x4000);
  for (u32 i = 0; i < kTestReverbRegs.size(); ++i) r.w16(0x1F801DC0 + 2 * i, kTestReverbRegs[i]);
}

}  // namespace psx::test
