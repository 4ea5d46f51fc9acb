// The GPU's draw log: while drawing is deferred (draw_queue.h), a drawing command is not decoded
// into a renderer call as it comes; its words are kept, in order, with the drawing-environment
// commands (GP0(E1)-(E6)) between them. What any command changes in the GPU's registers
// (GPUSTAT's E1 and E6 bits, a polygon's texpage, what GP1(10) reads back) is made at once, so
// the CPU sees the same GPU. When something needs VRAM (a frame, GPUREAD, a save state, a command
// that reads or streams VRAM), or the log is full, the registers go back to what they were before
// the log's first command, the commands are decoded and queued as they would have been then, and
// the registers end where they were. A state load (an environment's reset) drops the log
// undecoded: a game's frames between resets cost the words' copy and nothing more.
// A command is logged only where nothing but those registers shapes it: not in 480-line interlace
// without GP0(E1).10, where a primitive skips the rows of the field shown at its time.
#include <algorithm>

#include "gpu/gpu.h"

namespace psx {

Gpu::DecodeRegs Gpu::decode_regs() const {
  return {draw_mode_, texture_window_, area_top_left_, area_bottom_right_, draw_offset_, mask_bits_};
}

void Gpu::set_decode_regs(const DecodeRegs& r) {
  draw_mode_ = r.draw_mode, texture_window_ = r.texture_window, area_top_left_ = r.area_top_left;
  area_bottom_right_ = r.area_bottom_right, draw_offset_ = r.draw_offset, mask_bits_ = r.mask_bits;
  update_draw_state();
}

// Logs the command at w (whole, gp0_command_length() words) and makes its register effects, or
// answers false for the caller to execute it, after the log where that command reaches VRAM.
bool Gpu::log_command(const u32* w) {
  const u32 c = w[0] >> 24;
  const bool draws = (c >> 5) >= 1 && (c >> 5) <= 4;  // polygons, lines, rectangles, VRAM copies
  const bool environment = c >= 0xE1 && c <= 0xE6;
  // GP0(01) is logged for its place among the logged commands: it clears the CLUT cache between
  // them (Gpu::clear_cache()).
  if (!draws && !environment && c != 0x02 && c != 0x01) {
    // Transfers to and from VRAM stream words or read it; NOPs and GP0(1F) draw nothing.
    if ((c >> 5) == 5 || (c >> 5) == 6) replay_log();
    return false;
  }
  const bool polyline = (c >> 5) == 2 && (c & 0x08);
  const bool field_rows = (display_mode_ & 0x24) == 0x24 && !(draw_mode_ & 0x400);
  if (polyline || (field_rows && (c >> 5) <= 3 && (c >> 5) >= 1)) {
    replay_log();
    return false;
  }
  if (log_words_ == 0) {
    log_start_ = decode_regs();
    // Once, uninitialised: its pages become resident as the log first reaches them.
    if (!log_) log_.reset(new u32[kMaxLogWords + 16]);
  }
  const u32 n = fifo_needed_;  // the caller's length (gp0_write(), dma_write()), at most 16 words
  std::copy_n(w, n, log_.get() + log_words_);
  log_words_ += n;
  if (draws || c == 0x02) ++log_draws_;
  // A textured polygon's texpage rides in its second vertex's texcoord word (gp0_polygon()).
  if ((c >> 5) == 1 && (c & 0x04)) apply_texpage(w[(c & 0x10) ? 5 : 4] >> 16);
  if (environment) gp0_environment(w[0]);
  if (log_words_ >= kMaxLogWords) {
    // A run this long without a state load is not an episode that ends soon: the queue takes
    // the commands as they come again until the next load.
    replay_log();
    log_full_ = true;
    update_logging();
  }
  return true;
}

// The logged commands decoded and queued as they came, from the registers they found.
void Gpu::replay_log() {
  if (log_words_ == 0) return;
  const DecodeRegs now = decode_regs();
  set_decode_regs(log_start_);
  logging_ = false;  // the commands replayed go to the queue
  for (size_t i = 0; i < log_words_; i += gp0_command_length(log_[i] >> 24)) {
    if (log_frame_ && i == log_frame_at_) draw_.frame_due(log_frame_area_), log_frame_ = false;
    gp0_execute(&log_[i]);
  }
  if (log_frame_) draw_.frame_due(log_frame_area_), log_frame_ = false;
  update_logging();
  set_decode_regs(now);
  log_words_ = 0;
  log_draws_ = 0;
}

void Gpu::set_draw_log(bool on) {
  replay_log();
  log_wanted_ = on;
  update_logging();
}

void Gpu::update_logging() { logging_ = log_wanted_ && !log_full_ && draw_.deferred(); }

void Gpu::drop_log() {
  log_full_ = false;
  update_logging();
  log_words_ = 0;
  log_draws_ = 0;
  log_frame_ = false;
}

}  // namespace psx
