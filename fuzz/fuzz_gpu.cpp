// Guest-side fuzzing of the GPU (src/gpu/gpu.h) and its DMA channel: random GP0 command words,
// GP1 display commands, GPUREAD/GPUSTAT reads, RAM contents and DMA register writes (block and
// linked-list transfers on channel 2, ordering tables on channel 6), with the scheduler run in
// between so VBlank, transfers and IRQs happen, with drawing deferred or not. Odd commands and
// wild DMA are guest behaviour: they must never touch host memory outside VRAM and RAM. Each
// input is a list of operations, an op byte then its arguments; emulated time is capped per input
// so a run stays short.
#include <algorithm>

#include "core/bus.h"
#include "core/dma.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "fuzz_util.h"
#include "gpu/gpu.h"

using namespace psx;

namespace {

// DMA registers an op may write: channel 2 (GPU) and 6 (OTC) MADR/BCR/CHCR, DPCR, DICR.
constexpr u32 kDmaRegs[] = {0x20, 0x24, 0x28, 0x60, 0x64, 0x68, 0x70, 0x74};
// About two frames: a DMA list feeding GP0 large polygons draws far more per emulated cycle than
// hardware could (drawing time is not modelled), so the budget bounds host time, not realism.
constexpr Cycles kMaxCycles = 1'200'000;

struct Rig {
  Scheduler sched;
  InterruptController irq;
  Bus bus{sched, irq};
  Gpu gpu{sched, irq};
  Dma dma{sched, irq, bus};
  Rig() { dma.connect(Dma::Gpu, &gpu); }

  void run(Cycles cycles) {
    const Cycles end = sched.now() + cycles;
    while (sched.now() < end) {
      sched.advance(std::min(sched.next_deadline(), end) - sched.now());
      sched.run_due_events();
    }
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  if (size > 16 * 1024) return 0;  // bounds the drawing work per input
  Rig r;
  // Odd-sized inputs run with drawing deferred (the draw log and queue, gp0_log.cpp), even ones
  // drawing at once, so the ops keep their meaning either way.
  r.gpu.set_deferred_drawing(size & 1);
  psxfuzz::Reader in(data, size);
  Cycles budget = kMaxCycles;
  u32 words[256];
  while (!in.empty()) {
    switch (in.byte() % 8) {
      case 0: r.gpu.io_write(0, in.word(), 4); break;  // GP0
      case 1: r.gpu.io_write(4, in.word(), 4); break;  // GP1
      case 2: r.gpu.io_read(0, 4); break;              // GPUREAD
      case 3: r.gpu.io_read(4, 4); break;              // GPUSTAT
      case 4: {  // a RAM word, e.g. a linked-list node or a block for DMA
        const u32 addr = in.word() & (Bus::kRamSize - 4);
        const u32 v = in.word();
        for (int i = 0; i < 4; ++i) r.bus.ram()[addr + i] = static_cast<u8>(v >> (8 * i));
        break;
      }
      case 5: {
        const u32 reg = kDmaRegs[in.byte() % std::size(kDmaRegs)];
        r.dma.io_write(reg, in.word(), 4);
        break;
      }
      case 6: {
        const Cycles n = std::min<Cycles>(budget, Cycles{in.u16()} * 64);
        budget -= n;
        r.run(n);
        break;
      }
      case 7: {  // the GPU's DMA port driven directly, as a block transfer would
        const u32 n = in.byte();
        if (in.byte() & 1) {
          for (u32 i = 0; i < n; ++i) words[i] = in.word();
          r.gpu.dma_write(words, n);
        } else {
          r.gpu.dma_read(words, n);
        }
        break;
      }
    }
  }
  return 0;
}
