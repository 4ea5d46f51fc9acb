// The PlayStation GPU (psx-spx "Graphics Processing Unit (GPU)"), mapped at 0x1F801810:
// GP0 (rendering commands, VRAM transfers) / GPUREAD at +0, GP1 (display control) / GPUSTAT at
// +4, and DMA channel 2. Command processing lives here and in gp0_commands.cpp; drawing is done by
// a Renderer backend; video timing and frame output are separate helpers this class owns.
#pragma once
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/io_device.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "core/state.h"
#include "core/types.h"
#include "gpu/draw_queue.h"
#include "gpu/frame_output.h"
#include "gpu/renderer.h"
#include "gpu/video_timing.h"

namespace psx {

namespace gpu {
// The drawing area (GP0(E3)/(E4)) moved by minus the drawing offset (E5), with exclusive right
// and bottom ends: what the drawing time (gp0_draw_time.cpp) clips positions to as commands give
// them, before the offset.
struct TimeArea {
  s32 left = 0, top = 0, right_end = 1, bottom_end = 1;
};
}  // namespace gpu

class Gpu final : public IoDevice, public DmaPort {
 public:
  static constexpr u32 kBase = 0x1F801810;
  static constexpr u32 kSize = 16;

  Gpu(Scheduler& sched, InterruptController& irq);

  u32 io_read(u32 offset, u32 width) override;
  void io_write(u32 offset, u32 value, u32 width) override;

  void dma_write(const u32* words, u32 count) override;
  void dma_read(u32* words, u32 count) override;
  bool dma_request() const override;
  Cycles dma_block_cycles(u32 words) const override;  // gp0_draw_time.cpp

  void gp0_write(u32 word);
  void gp1_write(u32 word);
  u32 gpuread();
  u32 gpustat() const;

  // Replaces the drawing backend (the software renderer by default), handing VRAM over.
  void set_renderer(std::unique_ptr<gpu::Renderer> renderer);
  const gpu::Renderer& renderer() const { return *renderer_; }

  void set_video_signals(VideoSignals* signals) { timing_.set_signals(signals); }
  VideoClock& video_clock() { return timing_; }
  // Called at the start of each VBlank, after the frame was noted.
  std::function<void()> on_vblank;

  // The displayed picture as RGB888 at the renderer's scale, as VRAM was at the last VBlank. It
  // is converted on the first request after that VBlank (draw_queue.h), so these draw what is
  // queued first; they are const because the answer is the same as if done at the VBlank.
  const u8* display_rgb() const { return display().rgb(); }
  u32 display_width() const { return display().width(); }
  u32 display_height() const { return display().height(); }
  const gpu::FrameOutput& display() const {
    settle_log();
    draw_.frame_ready();
    return output_;
  }
  const u16* vram() const {
    settle_log();
    draw_.flush();
    return renderer_->vram();
  }
  // When nothing looks at pixels, drawing commands may wait until something reads VRAM or asks
  // for a frame (draw_queue.h); the results are the same either way. Off draws what waits. Only
  // the software renderer defers: the queue's pruning follows its coverage rules.
  void set_deferred_drawing(bool on);
  bool deferred_drawing() const { return draw_.deferred(); }
  // Drawing calls waiting: queued (draw_queue.h) or in the draw log (gp0_log.cpp), and of those
  // the logged ones.
  size_t queued_draws() const { return draw_.size() + log_draws_; }
  size_t logged_draws() const { return log_draws_; }
  // The draw log, on by default, keeps deferred drawing commands undecoded (gp0_log.cpp); off,
  // they are decoded and queued as they come (what is logged is queued first).
  void set_draw_log(bool on);
  // The log's words at most (2 MiB): filled, it is decoded, and commands are queued as they come
  // until the next state load.
  static constexpr size_t kMaxLogWords = size_t{1} << 19;
  // The whole VRAM as 1024x512 RGB888, converted on each call.
  const u8* vram_rgb();

  // PNG files of the display area (as VRAM holds it now) and of all of VRAM; false with `error`
  // set on failure.
  bool write_display_png(const std::string& path, std::string& error) const;
  bool write_vram_png(const std::string& path, std::string& error);

  const gpu::VideoTiming& timing() const { return timing_; }

  void do_state(StateIO& s);
  // A token for VRAM as it is now, which a snapshot keeps (Console::Snapshot): VRAM keeps its
  // token while nothing draws into it, and restoring a snapshot whose token it still holds
  // passes over the 1 MiB the snapshot holds instead of copying it back.
  std::shared_ptr<const void> vram_token();
  // The next do_state() load restores a snapshot taken with `token` (null: any other state).
  void expect_vram(std::shared_ptr<const void> token) { expected_vram_ = std::move(token); }

 private:
  enum class Gp0Mode : u8 { Command, Polyline, CpuToVram };
  struct Transfer {  // a GP0(A0)/(C0) rectangle being streamed
    u32 x = 0, y = 0, width = 0, height = 0;
    u32 col = 0, row = 0;
    bool active = false;
  };

  // GP0 (gp0_commands.cpp)
  // Words per command (the command word included; a polyline up to its first segment).
  static const std::array<u8, 256> kGp0Lengths;
  static u32 gp0_command_length(u32 command) { return kGp0Lengths[command & 0xFF]; }
  // A whole command's words: the FIFO's, or a DMA block's where it lies (dma_write()).
  void gp0_execute(const u32* w);
  void gp0_polygon(const u32* w);
  void gp0_line(const u32* w);
  void gp0_polyline_word(u32 word);
  void gp0_rectangle(const u32* w);
  void gp0_fill_rectangle(const u32* w);
  void gp0_copy_rectangle(const u32* w);
  void gp0_copy_to_vram(const u32* w);
  void gp0_copy_from_vram(const u32* w);
  void gp0_environment(u32 word);  // E1-E6
  void gp0_draw_mode(u32 word);
  void gp0_texture_window(u32 word);
  void gp0_draw_area_top_left(u32 word);
  void gp0_draw_area_bottom_right(u32 word);
  void gp0_draw_offset(u32 word);
  void gp0_mask_bit(u32 word);
  void gp0_irq();
  u16 clut_load(u32 clut);
  void clear_cache();
  void upload_pixels(const u16* pixels, u32 count);
  // Drawing time (gp0_draw_time.cpp): how long a command keeps the GPU busy, booked on the
  // timeline as it arrives.
  Cycles draw_time(const u32* w) const;
  void book_drawing(Cycles time);
  void book_line(const gpu::Vertex& a, const gpu::Vertex& b);
  void watch_drawing();
  bool drawing() const { return sched_.now() < busy_until_; }
  bool fifo_empty() const { return sched_.now() >= fifo_empty_at_; }
  void set_position(gpu::Vertex& v, u32 xy) const;
  void update_draw_state();
  const gpu::DrawState& draw_state();
  void apply_texpage(u32 texpage);

  // The draw log (gp0_log.cpp): while drawing is deferred, drawing commands are kept as the words
  // that came, with their effects on the GPU's registers made at once, and decoded only when
  // something needs VRAM (or the log is full); a state load drops them undecoded.
  struct DecodeRegs {
    u32 draw_mode, texture_window, area_top_left, area_bottom_right, draw_offset, mask_bits;
  };
  bool log_command(const u32* w);
  void replay_log();
  void settle_log() const { const_cast<Gpu*>(this)->replay_log(); }
  void drop_log();
  void update_logging();
  DecodeRegs decode_regs() const;
  void set_decode_regs(const DecodeRegs& r);

  // GP1 (gpu.cpp)
  void gp1_reset();
  void gp1_reset_command_buffer();
  void gp1_display_mode(u32 word);
  void gp1_gpu_info(u32 word);
  bool field_line_odd() const;
  void vblank_started();
  gpu::DisplayArea display_area() const;

  Scheduler& sched_;
  InterruptController& irq_;
  std::unique_ptr<gpu::Renderer> renderer_;
  gpu::VideoTiming timing_;
  // Converted and drawn on demand, which const readers may trigger.
  mutable gpu::FrameOutput output_;
  mutable gpu::DrawQueue draw_{output_};
  std::vector<u8> vram_rgb_;
  bool deferral_wanted_ = false;
  // vram_token(): the token VRAM holds and draw_.executed() when it got it; expect_vram()'s.
  std::shared_ptr<const void> vram_token_, expected_vram_;
  u64 token_draws_ = 0;

  std::unique_ptr<u32[]> log_;  // kMaxLogWords + 16 words, log_words_ of them used
  size_t log_words_ = 0;
  size_t log_draws_ = 0;  // drawing commands in the log
  DecodeRegs log_start_{};  // the registers before the log's first command
  bool log_full_ = false;  // the log filled up: off until the next state load
  bool log_wanted_ = true;  // set_draw_log()
  bool logging_ = false;    // commands go to the log now: wanted, not full, drawing deferred
  // The VBlank frame noted while the log held log_frame_at_ words (DrawQueue::frame_due there).
  bool log_frame_ = false;
  size_t log_frame_at_ = 0;
  gpu::DisplayArea log_frame_area_;

  // GP0 state
  Gp0Mode gp0_mode_ = Gp0Mode::Command;
  u32 fifo_[16] = {};
  u32 fifo_len_ = 0;
  u32 fifo_needed_ = 0;
  gpu::Vertex polyline_last_;
  u32 polyline_colour_ = 0;
  bool polyline_shaded_ = false;
  bool polyline_semi_ = false;
  bool polyline_have_colour_ = false;
  Transfer upload_;    // GP0(A0)
  Transfer download_;  // GP0(C0)
  u32 gpuread_latch_ = 0;
  // The GPU draws until busy_until_ (GPUSTAT.26); the last command booked waits in the FIFO
  // until fifo_empty_at_ (GPUSTAT.28).
  Cycles busy_until_ = 0, fifo_empty_at_ = 0;
  Scheduler::Handle draw_event_;  // "gpu.draw", at the next of those times once polled (watch_drawing())
  // The CLUT cache's contents (clut_load()): the CLUT attribute it was loaded from (kNoClut
  // after GP0(01) or a reset) and whether it holds 256 entries; the entries are the renderer's.
  static constexpr u32 kNoClut = 0xFFFFFFFF;
  u32 clut_tag_ = kNoClut;
  bool clut_wide_ = false;

  // Drawing environment registers (raw values for GPUSTAT and GP1(10)).
  u32 draw_mode_ = 0;        // E1 bits 0-13
  u32 texture_window_ = 0;   // E2 bits 0-19
  u32 area_top_left_ = 0;    // E3 bits 0-18
  u32 area_bottom_right_ = 0;  // E4 bits 0-18
  u32 draw_offset_ = 0;      // E5 bits 0-21
  u32 mask_bits_ = 0;        // E6 bits 0-1
  s32 offset_x_ = 0, offset_y_ = 0;
  gpu::DrawState ds_;
  gpu::TimeArea time_area_;

  // Display control registers.
  bool irq_flag_ = false;           // GPUSTAT.24
  bool display_disabled_ = true;    // GPUSTAT.23
  u32 dma_direction_ = 0;           // GP1(04)
  u32 display_start_ = 0;           // GP1(05)
  u32 horizontal_range_ = 0;        // GP1(06)
  u32 vertical_range_ = 0;          // GP1(07)
  u32 display_mode_ = 0;            // GP1(08) bits 0-7
  bool texture_disable_allowed_ = false;  // GP1(09)
};

}  // namespace psx
