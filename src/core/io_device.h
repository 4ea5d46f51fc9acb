// Interfaces between the bus/DMA and the hardware blocks mapped into the I/O region
// (0x1F801000-0x1F802FFF). Each block implements the ones it needs; the console wires them up.
#pragma once
#include "core/types.h"

namespace psx {

// A block with registers in the I/O region. `offset` is relative to the base the block was mapped
// at; `width` is the access size in bytes (1, 2 or 4). A CPU store narrower than the register it
// reaches arrives as a write of the whole register (Bus::io_write()); each block implements the
// documented behaviour of the other accesses to its own registers.
class IoDevice {
 public:
  virtual ~IoDevice() = default;
  virtual u32 io_read(u32 offset, u32 width) = 0;
  virtual void io_write(u32 offset, u32 value, u32 width) = 0;
};

// The device side of a DMA channel (MDECin/out, GPU, CD-ROM, SPU). The DMA controller moves
// words between RAM and the device in blocks; `dma_request` is the device's DRQ line, which
// sync mode 1 (block) transfers wait on; `dma_block_cycles` is how long the device itself takes
// to consume (or refill) a block of `words` through its FIFO before it asks for the next one.
class DmaPort {
 public:
  virtual ~DmaPort() = default;
  virtual void dma_write(const u32* words, u32 count) = 0;  // RAM -> device
  virtual void dma_read(u32* words, u32 count) = 0;         // device -> RAM
  virtual bool dma_request() const { return true; }
  virtual Cycles dma_block_cycles(u32 /*words*/) const { return 0; }
};

// Video timing edges the GPU exports to the root counters (timers 0 and 1 count dots and
// HBlanks and can synchronise to the blanking periods). Called at the scheduler time of the edge.
// HBlank edges come only while wants_hblank() is true (timer 0 synchronised to HBlank): two a
// scanline would otherwise be the busiest events of the console. Timer 1 counts HBlanks without
// them (VideoClock::hblanks_by).
class VideoSignals {
 public:
  virtual ~VideoSignals() = default;
  virtual bool wants_hblank() const = 0;
  virtual void hblank_changed(bool active) = 0;
  virtual void vblank_changed(bool active) = 0;
  // The dot clock is the GPU video clock (psx-spx "GPU Timings": 53.693175 MHz NTSC, 53.203425 MHz
  // PAL) divided by the video clock cycles per dot of the horizontal resolution (10, 8, 7, 5 or 4).
  // Timer 0 counts it, so it must use the same clock as the GPU's scanlines.
  virtual void dot_clock_changed(u64 video_hz, u32 video_cycles_per_dot) = 0;
};

// The video timing as the root counters query it: a block that starts wanting HBlank edges
// (VideoSignals::wants_hblank) reads the HBlank state at that moment here, before the change, and
// after any change of what it wants asks for the edges to be booked again.
class VideoClock {
 public:
  virtual ~VideoClock() = default;
  virtual bool hblank_now() = 0;
  virtual void hblank_wanted_changed() = 0;
  // HBlank starts from power-on up to and including cycle t (t not before the last edge the
  // video timing delivered), in closed form: how timer 1 counts HBlanks, with no event per line.
  virtual u64 hblanks_by(Cycles t) const = 0;
  // The cycle of HBlank start number n as hblanks_by() counts (n past the last delivered edge):
  // when timer 1, counting HBlanks, reaches its interrupt.
  virtual Cycles hblank_time(u64 n) const = 0;
};

}  // namespace psx
