// GPU video timing: scanline/frame counting and the blanking edges on the scheduler.
#include "gpu/video_timing.h"

#include <algorithm>

namespace psx::gpu {

VideoTiming::VideoTiming(Scheduler& sched, std::function<void()> vblank_started)
    : sched_(sched), vblank_started_(std::move(vblank_started)) {
  event_ = sched_.add_event("gpu.video", [this](Cycles) { on_event(); });
  pos_.edge_at = sched_.now();
  advance(pos_, kActiveCycles);
  book();
}

void VideoTiming::set_signals(VideoSignals* signals) {
  sync();
  signals_ = signals;
  if (signals_) signals_->dot_clock_changed(video_hz(), dot_divider_);
  book();
}

void VideoTiming::set_mode(bool pal, bool interlaced, u32 dot_divider) {
  // The lines so far ran in the old mode; the edge already due keeps its time, as on the console.
  sync();
  bool clock_changed = pal != pal_ || dot_divider != dot_divider_;
  pal_ = pal;
  interlaced_ = interlaced;
  if (!interlaced_) odd_field_ = false;
  dot_divider_ = dot_divider;
  if (clock_changed && signals_) signals_->dot_clock_changed(video_hz(), dot_divider_);
  book();
}

u32 VideoTiming::lines_per_frame() const {
  u32 lines = pal_ ? kPalLines : kNtscLines;
  // Interlaced frames are 262.5/312.5 lines: the odd field is one line shorter.
  return interlaced_ && odd_field_ ? lines - 1 : lines;
}

u32 VideoTiming::next_line(u32 line) const { return line + 1 >= lines_per_frame() ? 0 : line + 1; }

// Converts video clock cycles to CPU cycles exactly, carrying the remainder to the next edge.
void VideoTiming::advance(Position& p, u64 video_cycles) const {
  u64 hz = video_hz();
  u64 total = p.remainder + video_cycles * kCpuClockHz;
  p.edge_at += total / hz;
  p.remainder = total % hz;
}

// The edge at p.edge_at: HBlank starts (the line's active part is over), or it ends and the next
// line starts.
void VideoTiming::pass_edge(Position& p) const {
  if (!p.hblank) {
    p.hblank = true;
    ++p.hblanks;
    advance(p, line_cycles() - kActiveCycles);
    return;
  }
  p.hblank = false;
  p.line = next_line(p.line);
  advance(p, kActiveCycles);
}

bool VideoTiming::next_edge_changes_vblank(const Position& p) const {
  if (!p.hblank) return false;
  u32 line = next_line(p.line);
  return vblank_ ? line == (pal_ ? kPalFirstVisible : kNtscFirstVisible)
                 : line == (pal_ ? kPalVblankStart : kNtscVblankStart);
}

void VideoTiming::sync() const {
  if (hblank_wanted()) return;
  // Inside another event's callback, only the edges an event per edge would have run by then.
  const Cycles now = sched_.horizon(event_);
  if (pos_.edge_at <= now) pass_lines(pos_, now);
  while (pos_.edge_at <= now && !next_edge_changes_vblank(pos_)) pass_edge(pos_);
}

// Two edges (an HBlank start and a line start, in either order) take one line's video cycles,
// and advance() carries the remainder exactly, so n lines at once land where 2n edges one by one
// would. Whole lines are passed while the edge after them is due by `now` and none of them
// reaches the line whose start changes VBlank; the last edges are left to pass_edge().
void VideoTiming::pass_lines(Position& p, Cycles now) const {
  const u64 by_time = lines_by(p, now);
  const u32 lines = lines_per_frame();
  const u32 boundary = vblank_ ? (pal_ ? kPalFirstVisible : kNtscFirstVisible) : (pal_ ? kPalVblankStart : kNtscVblankStart);
  const u32 before_boundary = (boundary + lines - p.line - 1) % lines;  // lines line+1.. that are not it
  const u64 n = std::min<u64>(by_time, before_boundary);
  if (n == 0) return;
  p.line = static_cast<u32>((p.line + n) % lines);
  p.hblanks += n;  // a line holds one HBlank start
  advance(p, n * line_cycles());
}

u64 VideoTiming::lines_by(const Position& p, Cycles now) const {
  const u64 hz = video_hz();
  // edge_at after n lines = edge_at + (remainder + n * line_cycles() * kCpuClockHz) / hz <= now.
  return ((now - p.edge_at + 1) * hz - p.remainder - 1) / (u64{line_cycles()} * kCpuClockHz);
}

VideoTiming::Position VideoTiming::next_hblank(Position p) const {
  if (p.hblank) pass_edge(p);  // the line start before it
  return p;
}

u64 VideoTiming::hblanks_by(Cycles t) const {
  // The edges are evenly spaced in video cycles, so the starts past the position are counted
  // as pass_lines() counts lines, whatever the position has been brought up to.
  const Position p = next_hblank(pos_);
  return p.edge_at > t ? p.hblanks : p.hblanks + 1 + lines_by(p, t);
}

Cycles VideoTiming::hblank_time(u64 n) const {
  Position p = next_hblank(pos_);  // its edge is HBlank start number p.hblanks + 1
  advance(p, (n - p.hblanks - 1) * line_cycles());
  return p.edge_at;
}

bool VideoTiming::hblank_now() {
  sync();
  return pos_.hblank;
}

void VideoTiming::hblank_wanted_changed() { book(); }

void VideoTiming::on_event() {
  sync();
  if (pos_.edge_at <= sched_.horizon(event_)) deliver_edge();
  book();
}

// The edge at pos_.edge_at, with its signals: HBlank to the timers (when they want it), the
// blanking periods to the timers and VBlank starts to the GPU.
void VideoTiming::deliver_edge() {
  const bool changes_vblank = next_edge_changes_vblank(pos_);
  pass_edge(pos_);
  if (changes_vblank && vblank_) {
    vblank_ = false;
    if (signals_) signals_->vblank_changed(false);
  } else if (changes_vblank) {
    vblank_ = true;
    // A new interlaced field starts with each VBlank (GPUSTAT.13 and .31 follow it).
    if (interlaced_) odd_field_ = !odd_field_;
    if (signals_) signals_->vblank_changed(true);
    if (vblank_started_) vblank_started_();
  }
  if (hblank_wanted()) signals_->hblank_changed(pos_.hblank);
}

// Books the next edge someone needs as an event: every edge while the timers want HBlank edges,
// else the next line start that begins or ends VBlank, found in closed form. Edge times add up
// exactly (the remainder carries the fractions), so d lines after an edge is one advance of d
// whole lines.
void VideoTiming::book() {
  Position p = pos_;
  if (!hblank_wanted()) {
    if (!p.hblank) pass_edge(p);
    u32 target = vblank_ ? (pal_ ? kPalFirstVisible : kNtscFirstVisible) : (pal_ ? kPalVblankStart : kNtscVblankStart);
    u32 lines = lines_per_frame();
    u32 lines_to_target = (target + lines - next_line(p.line)) % lines;
    advance(p, u64{lines_to_target} * line_cycles());
  }
  sched_.schedule_at(event_, p.edge_at);
}

void VideoTiming::do_state(StateIO& s) {
  // Saved up to date, so a state does not depend on when the position was last asked for.
  if (!s.loading()) sync();
  // Version 2 adds the HBlank starts passed (version 1 loads them as 0: timer 1 counts from there).
  const u32 version = s.section("GPUT", 2, 1);
  s.boolean(pal_);
  s.boolean(interlaced_);
  s.pod(dot_divider_);
  s.pod(pos_.line);
  s.boolean(pos_.hblank);
  s.boolean(vblank_);
  s.boolean(odd_field_);
  s.pod(pos_.edge_at);
  s.pod(pos_.remainder);
  if (version >= 2) s.pod(pos_.hblanks);
  else pos_.hblanks = 0;
  s.end_section("GPUT");
}

}  // namespace psx::gpu
