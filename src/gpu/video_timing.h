// GPU video timing (psx-spx "GPU Timings"): scanlines of 3413 (NTSC) or 3406 (PAL) video clock
// cycles, 263/314 lines per progressive frame (262.5/312.5 interlaced, alternating), HBlank at the
// end of each line and VBlank between frames. Edges go to the timers through VideoSignals and
// VBlank starts go to the GPU. The scanline position is computed lazily from the scheduler's
// clock: an event is booked only for the next VBlank edge, or for every edge while the timers
// want HBlank edges; the lines between are passed when someone asks (GPUSTAT.31 reads the line).
#pragma once
#include <functional>

#include "core/io_device.h"
#include "core/scheduler.h"
#include "core/state.h"
#include "core/types.h"

namespace psx::gpu {

class VideoTiming : public VideoClock {
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

  // VBlank and the field change only at booked events; the line at every edge.
  bool in_vblank() const { return vblank_; }
  bool odd_field() const { return odd_field_; }
  u32 line() const {
    sync();
    return pos_.line;
  }
  bool pal() const { return pal_; }
  u32 lines_per_frame() const;
  // Video clock of the current standard.
  u64 video_hz() const { return pal_ ? kPalVideoHz : kNtscVideoHz; }

  bool hblank_now() override;
  void hblank_wanted_changed() override;
  u64 hblanks_by(Cycles t) const override;
  Cycles hblank_time(u64 n) const override;

  void do_state(StateIO& s);

 private:
  // Where the beam is: the current line, whether it is in HBlank, and when the next edge falls
  // (the scheduler time, and the fraction of a CPU cycle past it in 1/video_hz units, so that
  // edge times carry no rounding error).
  struct Position {
    u32 line = 0;
    bool hblank = false;
    Cycles edge_at = 0;
    u64 remainder = 0;
    u64 hblanks = 0;  // HBlank starts passed since power-on
  };

  void on_event();
  // Passes edges due by now that change nothing but the position: none while HBlank edges are
  // wanted (those are events), and never one that starts or ends VBlank.
  void sync() const;
  bool next_edge_changes_vblank(const Position& p) const;
  void pass_edge(Position& p) const;
  void pass_lines(Position& p, Cycles now) const;
  // Lines of `line_cycles` from p's next edge whose next edge is due by `now`: edges of p's next
  // kind at or before now, less the first.
  u64 lines_by(const Position& p, Cycles now) const;
  // p moved on to its next HBlank start (itself where that is its next edge).
  Position next_hblank(Position p) const;
  void advance(Position& p, u64 video_cycles) const;
  void deliver_edge();
  void book();
  u32 next_line(u32 line) const;
  // Video clock cycles per line of the current standard.
  u32 line_cycles() const { return pal_ ? kPalCyclesPerLine : kNtscCyclesPerLine; }
  bool hblank_wanted() const { return signals_ && signals_->wants_hblank(); }

  Scheduler& sched_;
  Scheduler::Handle event_;
  std::function<void()> vblank_started_;
  VideoSignals* signals_ = nullptr;

  bool pal_ = false;
  bool interlaced_ = false;
  u32 dot_divider_ = 10;
  mutable Position pos_;  // lazily brought up to date (sync), so const queries advance it
  bool vblank_ = true;
  bool odd_field_ = false;
};

}  // namespace psx::gpu
