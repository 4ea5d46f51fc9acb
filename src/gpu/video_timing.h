// GPU video timing (psx-spx "GPU Timings"): scanlines of 3413 (NTSC) or 3406 (PAL) video clock
// cycles, 263/314 lines per progressive frame (262.5/312.5 interlaced, alternating), HBlank at the
// end of each line and VBlank between frames. Runs on the scheduler; edges go to the timers
// through VideoSignals and VBlank starts go to the GPU.
#pragma once
#include <functional>

#include "core/io_device.h"
#include "core/scheduler.h"
#include "core/state.h"
#include "core/types.h"

namespace psx::gpu {

class VideoTiming {
 public:
  // Video clock frequencies (psx-spx): NTSC 53.693175 MHz, PAL 53.203425 MHz.
  static constexpr u64 kNtscVideoHz = 53693175;
  static constexpr u64 kPalVideoHz = 53203425;
  static constexpr u32 kNtscCyclesPerLine = 3413;
  static constexpr u32 kPalCyclesPerLine = 3406;
  static constexpr u32 kNtscLines = 263;
  static constexpr u32 kPalLines = 314;
  // Visible lines (240 NTSC / 288 PAL, the GP1(07) defaults' span); the rest is VBlank.
  static constexpr u32 kNtscFirstVisible = 16, kNtscVblankStart = 256;
  static constexpr u32 kPalFirstVisible = 20, kPalVblankStart = 308;
  // Active part of a line in video cycles (GP1(06) default range 260h..C60h); then HBlank.
  static constexpr u32 kActiveCycles = 2560;

  VideoTiming(Scheduler& sched, std::function<void()> vblank_started);

  void set_signals(VideoSignals* signals);
  // GP1(08): PAL/NTSC, interlace, and the dot clock divider of the horizontal resolution.
  void set_mode(bool pal, bool interlaced, u32 dot_divider);

  bool in_vblank() const { return vblank_; }
  bool odd_field() const { return odd_field_; }
  u32 line() const { return line_; }
  bool pal() const { return pal_; }
  u32 lines_per_frame() const;
  // Video clock of the current standard.
  u64 video_hz() const { return pal_ ? kPalVideoHz : kNtscVideoHz; }

  void do_state(StateIO& s);

 private:
  void on_edge();
  void start_line();
  void schedule_after(u32 video_cycles);

  Scheduler& sched_;
  Scheduler::Handle event_;
  std::function<void()> vblank_started_;
  VideoSignals* signals_ = nullptr;

  bool pal_ = false;
  bool interlaced_ = false;
  u32 dot_divider_ = 10;
  u32 line_ = 0;
  bool hblank_ = false;
  bool vblank_ = true;
  bool odd_field_ = false;
  Cycles edge_at_ = 0;      // scheduler time of the most recent edge
  u64 remainder_ = 0;       // fraction of a CPU cycle carried between edges, in 1/video_hz units
};

}  // namespace psx::gpu
