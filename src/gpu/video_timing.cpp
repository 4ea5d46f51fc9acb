// GPU video timing: scanline/frame counting and the blanking edges on the scheduler.
#include "gpu/video_timing.h"

namespace psx::gpu {

VideoTiming::VideoTiming(Scheduler& sched, std::function<void()> vblank_started)
    : sched_(sched), vblank_started_(std::move(vblank_started)) {
  event_ = sched_.add_event("gpu.video", [this](Cycles) { on_edge(); });
  edge_at_ = sched_.now();
  schedule_after(kActiveCycles);
}

void VideoTiming::set_signals(VideoSignals* signals) {
  signals_ = signals;
  if (signals_) signals_->dot_clock_changed(video_hz(), dot_divider_);
}

void VideoTiming::set_mode(bool pal, bool interlaced, u32 dot_divider) {
  bool clock_changed = pal != pal_ || dot_divider != dot_divider_;
  pal_ = pal;
  interlaced_ = interlaced;
  if (!interlaced_) odd_field_ = false;
  dot_divider_ = dot_divider;
  if (clock_changed && signals_) signals_->dot_clock_changed(video_hz(), dot_divider_);
}

u32 VideoTiming::lines_per_frame() const {
  u32 lines = pal_ ? kPalLines : kNtscLines;
  // Interlaced frames are 262.5/312.5 lines: the odd field is one line shorter.
  return interlaced_ && odd_field_ ? lines - 1 : lines;
}

// Converts video clock cycles to CPU cycles exactly, carrying the remainder to the next edge.
void VideoTiming::schedule_after(u32 video_cycles) {
  u64 hz = video_hz();
  u64 total = remainder_ + u64{video_cycles} * kCpuClockHz;
  edge_at_ += total / hz;
  remainder_ = total % hz;
  sched_.schedule_at(event_, edge_at_);
}

void VideoTiming::on_edge() {
  u32 line_cycles = pal_ ? kPalCyclesPerLine : kNtscCyclesPerLine;
  if (!hblank_) {
    hblank_ = true;
    if (signals_) signals_->hblank_changed(true);
    schedule_after(line_cycles - kActiveCycles);
    return;
  }
  hblank_ = false;
  start_line();
  if (signals_) signals_->hblank_changed(false);
  schedule_after(kActiveCycles);
}

void VideoTiming::start_line() {
  line_ = line_ + 1 >= lines_per_frame() ? 0 : line_ + 1;
  u32 first_visible = pal_ ? kPalFirstVisible : kNtscFirstVisible;
  u32 vblank_start = pal_ ? kPalVblankStart : kNtscVblankStart;
  if (line_ == first_visible && vblank_) {
    vblank_ = false;
    if (signals_) signals_->vblank_changed(false);
  } else if (line_ == vblank_start && !vblank_) {
    vblank_ = true;
    // A new interlaced field starts with each VBlank (GPUSTAT.13 and .31 follow it).
    if (interlaced_) odd_field_ = !odd_field_;
    if (signals_) signals_->vblank_changed(true);
    if (vblank_started_) vblank_started_();
  }
}

void VideoTiming::do_state(StateIO& s) {
  s.section("GPUT", 1);
  s.boolean(pal_);
  s.boolean(interlaced_);
  s.pod(dot_divider_);
  s.pod(line_);
  s.boolean(hblank_);
  s.boolean(vblank_);
  s.boolean(odd_field_);
  s.pod(edge_at_);
  s.pod(remainder_);
  s.end_section("GPUT");
}

}  // namespace psx::gpu
