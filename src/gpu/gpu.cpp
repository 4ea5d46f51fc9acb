// GPU registers: GPUSTAT/GPUREAD reads, GP1 display control, the DMA port, VBlank output and
// save states. GP0 command decoding is in gp0_commands.cpp.
#include "gpu/gpu.h"

#include <algorithm>
#include <utility>

#include "gpu/software_renderer.h"
#include "gpu/vram.h"
#include "util/png_writer.h"

namespace psx {

Gpu::Gpu(Scheduler& sched, InterruptController& irq)
    : sched_(sched),
      irq_(irq),
      renderer_(std::make_unique<gpu::SoftwareRenderer>()),
      timing_(sched, [this] { vblank_started(); }) {
  draw_event_ = sched_.add_event("gpu.draw", [](Cycles) {});  // marks a GPUSTAT change (watch_drawing())
  draw_.set_target(renderer_.get());
  gp1_reset();
}

// GP0/GPUREAD at +0, GP1/GPUSTAT at +4; +8/+C mirror them. Narrow reads see the addressed bytes.
u32 Gpu::io_read(u32 offset, u32 width) {
  if (offset & 4) watch_drawing();
  u32 value = (offset & 4) ? gpustat() : gpuread();
  return value >> ((offset & 3) * 8);
}

void Gpu::io_write(u32 offset, u32 value, u32 width) {
  if (offset & 4)
    gp1_write(value);
  else
    gp0_write(value);
}

u32 Gpu::gpustat() const {
  const bool interlaced = display_mode_ & 0x20;
  u32 s = draw_mode_ & 0x7FF;                        // 0-10 from E1
  s |= (mask_bits_ & 3) << 11;                       // 11-12 from E6
  // 13: the interlace field being drawn, which is the one not displayed, so the complement of the
  // field GPUSTAT.31 shows (a BIOS shell waits for 31=1 with 13=0, then the reverse); always 1
  // without interlace (psx-spx "GPU Status Register", ODE2).
  s |= u32{interlaced ? !timing_.odd_field() : true} << 13;
  s |= ((display_mode_ >> 7) & 1) << 14;             // "reverse flag"
  s |= ((draw_mode_ >> 11) & 1) << 15;               // texture disable
  s |= ((display_mode_ >> 6) & 1) << 16;             // horizontal resolution 2 (368)
  s |= (display_mode_ & 0x3F) << 17;                 // 17-22: hres 1, vres, PAL, 24-bit, interlace
  s |= u32{display_disabled_} << 23;
  s |= u32{irq_flag_} << 24;
  // 26: ready for a command word: no command's parameters, polyline vertices or transfer data
  // still to come (psx-spx "Ready Bits": 0 while the GPU wants more parameters or data; Mednafen
  // too, while its FIFO holds words), and nothing drawing (gp0_draw_time.cpp).
  // 28: ready for a DMA block: the command FIFO is empty, which a VRAM-to-CPU transfer waiting
  // to be read leaves it (on a console, DrawSync's wait for bit 28 after GP0(C0) ends: ps1-tests
  // gpu/bandwidth), and a drawing command alone too: only one waiting behind it fills it
  // (ps1-tests gpu/gpustat: 26 = 0, 28 = 1 while one rectangle sent by the CPU draws; both 0
  // while a DMA list's second one waits). 25 follows 28 in direction 2 and 27 in direction 3.
  const bool ready_cmd = gp0_mode_ == Gp0Mode::Command && fifo_len_ == 0 && !download_.active && !drawing();
  const bool ready_dma = fifo_empty();
  s |= u32{ready_cmd} << 26;
  s |= u32{download_.active} << 27;   // ready to send VRAM to the CPU
  s |= u32{ready_dma} << 28;
  const bool request[4] = {false, true, ready_dma, download_.active};
  s |= u32{request[dma_direction_]} << 25;
  s |= dma_direction_ << 29;
  s |= u32{field_line_odd()} << 31;
  return s;
}

// GPUSTAT.31 (ODE): the displayed line is odd. psx-spx "GPU Status Register": it changes per
// frame (the field) in 480-line interlace, per scanline in 240-line modes, and is 0 in VBlank.
bool Gpu::field_line_odd() const {
  if (timing_.in_vblank()) return false;
  if ((display_mode_ & 0x24) == 0x24) return timing_.odd_field();
  return timing_.line() & 1;
}

// The request the DMA controller polls once per linked-list node, by GP1(04): off never, FIFO
// not full (always, here), ready for a block (always: commands execute as they arrive, and their
// drawing time is not made the DMA's), ready to send VRAM. Computed alone, without GPUSTAT.
bool Gpu::dma_request() const {
  switch (dma_direction_) {
    case 0: return false;
    case 1:
    case 2: return true;
    default: return download_.active;
  }
}

u32 Gpu::gpuread() {
  if (!download_.active) return gpuread_latch_;
  // GP0(C0): two pixels per word, low halfword first, wrapping at the VRAM edges.
  const u16* v = vram();
  u32 word = 0;
  for (u32 half = 0; half < 2 && download_.active; ++half) {
    word |= u32{v[gpu::vram_index(download_.x + download_.col, download_.y + download_.row)]} << (16 * half);
    if (++download_.col == download_.width) {
      download_.col = 0;
      if (++download_.row == download_.height) download_.active = false;
    }
  }
  gpuread_latch_ = word;
  return word;
}

void Gpu::dma_write(const u32* words, u32 count) {
  u16 pixels[512];
  u32 i = 0;
  while (i < count) {
    if (gp0_mode_ == Gp0Mode::Command && fifo_len_ == 0) {
      // A whole command in the block runs where it lies, and the FIFO is left empty, as
      // gp0_write() would leave it word by word.
      const u32 needed = gp0_command_length(words[i] >> 24);
      if (count - i >= needed) {
        fifo_needed_ = needed;
        const u32* command = words + i;
        i += needed;
        book_drawing(draw_time(command));
        gp0_execute(command);
        continue;
      }
    }
    if (gp0_mode_ != Gp0Mode::CpuToVram) {
      gp0_write(words[i++]);
      continue;
    }
    // Batch the transfer's words into rows (the renderer is called per row, not per pixel).
    u32 n = 0;
    u32 left = (upload_.width * (upload_.height - upload_.row) - upload_.col + 1) / 2;
    while (i < count && n < 512 && n / 2 < left) {
      pixels[n++] = static_cast<u16>(words[i]);
      pixels[n++] = static_cast<u16>(words[i++] >> 16);
    }
    upload_pixels(pixels, n);
  }
}

void Gpu::dma_read(u32* words, u32 count) {
  for (u32 i = 0; i < count; ++i) words[i] = gpuread();
}

void Gpu::gp1_write(u32 word) {
  const u32 command = (word >> 24) & 0x3F;
  // The draw log decodes with the display mode and GP1(09) it was logged under.
  if (command == 0x00 || command == 0x08 || command == 0x09) replay_log();
  switch (command) {
    case 0x00: gp1_reset(); break;
    case 0x01: gp1_reset_command_buffer(); break;
    case 0x02: irq_flag_ = false; break;                 // acknowledge GPU interrupt
    case 0x03: display_disabled_ = word & 1; break;      // display enable (0 = on)
    case 0x04: dma_direction_ = word & 3; break;         // DMA direction / data request
    case 0x05: display_start_ = word & 0x7FFFF; break;   // start of display area X 0-9, Y 10-18
    case 0x06: horizontal_range_ = word & 0xFFFFFF; break;
    case 0x07: vertical_range_ = word & 0xFFFFF; break;
    case 0x08: gp1_display_mode(word); break;
    case 0x09: texture_disable_allowed_ = word & 1; break;
    default:
      // 10h-1Fh: GPU info; 0Ah-0Fh and 20h-3Fh have no effect on this (1 MiB VRAM) GPU.
      if (command >= 0x10 && command <= 0x1F) gp1_gpu_info(word);
      break;
  }
}

// GP1(00) (psx-spx): clears the FIFO and IRQ, display off, DMA off, display area at 0,
// ranges 200h..C00h x 10h..100h, 320x240 NTSC mode 0, and GP0(E1)-(E6) all zero.
void Gpu::gp1_reset() {
  gp1_reset_command_buffer();
  download_.active = false;
  busy_until_ = fifo_empty_at_ = 0;  // whatever was drawing stops
  sched_.cancel(draw_event_);
  irq_flag_ = false;
  clear_cache();
  display_disabled_ = true;
  dma_direction_ = 0;
  display_start_ = 0;
  horizontal_range_ = 0x200 | (0xC00 << 12);
  vertical_range_ = 0x10 | (0x100 << 10);
  gp1_display_mode(0);
  for (u32 e = 0xE1; e <= 0xE6; ++e) gp0_write(e << 24);
}

// GP1(01): drops any half-received command and ends a CPU->VRAM transfer.
void Gpu::gp1_reset_command_buffer() {
  gp0_mode_ = Gp0Mode::Command;
  fifo_len_ = 0;
  upload_.active = false;
}

void Gpu::gp1_display_mode(u32 word) {
  display_mode_ = word & 0xFF;
  // Dot clock dividers per horizontal resolution (psx-spx): 256:10, 320:8, 512:5, 640:4, 368:7.
  static constexpr u32 kDivider[4] = {10, 8, 5, 4};
  u32 divider = (display_mode_ & 0x40) ? 7 : kDivider[display_mode_ & 3];
  timing_.set_mode(display_mode_ & 0x08, display_mode_ & 0x20, divider);
}

// GP1(10): the answer goes to GPUREAD; indices without an answer leave GPUREAD unchanged.
void Gpu::gp1_gpu_info(u32 word) {
  switch (word & 0xF) {
    case 0x2: gpuread_latch_ = texture_window_; break;
    case 0x3: gpuread_latch_ = area_top_left_; break;
    case 0x4: gpuread_latch_ = area_bottom_right_; break;
    case 0x5: gpuread_latch_ = draw_offset_; break;
    case 0x7: gpuread_latch_ = 2; break;  // GPU type: 2 = the 208-pin GPU
    case 0x8: gpuread_latch_ = 0; break;
    default: break;
  }
}

gpu::DisplayArea Gpu::display_area() const {
  static constexpr u32 kWidths[4] = {256, 320, 512, 640};
  gpu::DisplayArea a;
  a.x = display_start_ & 0x3FF;
  a.y = (display_start_ >> 10) & 0x1FF;
  a.width = (display_mode_ & 0x40) ? 368 : kWidths[display_mode_ & 3];
  u32 y1 = vertical_range_ & 0x3FF, y2 = (vertical_range_ >> 10) & 0x3FF;
  u32 max_lines = (display_mode_ & 0x08) ? 288 : 240;
  a.height = std::min(y2 > y1 ? y2 - y1 : 0, max_lines);
  if ((display_mode_ & 0x24) == 0x24) a.height *= 2;  // 480-line interlace shows both fields
  a.rgb24 = display_mode_ & 0x10;
  a.enabled = !display_disabled_;
  return a;
}

std::shared_ptr<const void> Gpu::vram_token() {
  replay_log();
  if (!vram_token_ || draw_.executed() != token_draws_) {
    vram_token_ = std::make_shared<const int>(0);  // stands for VRAM's contents now
    token_draws_ = draw_.executed();
  }
  return vram_token_;
}

// The picture is taken again from the new renderer, at its scale, from VRAM as it is now.
void Gpu::set_renderer(std::unique_ptr<gpu::Renderer> renderer) {
  renderer->load_vram(vram());
  renderer->set_clut_cache(renderer_->clut_cache());
  renderer_ = std::move(renderer);
  draw_.set_target(renderer_.get());
  draw_.frame_due(display_area());
  set_deferred_drawing(deferral_wanted_);
}

void Gpu::set_deferred_drawing(bool on) {
  deferral_wanted_ = on;
  replay_log();
  draw_.set_deferred(on && dynamic_cast<gpu::SoftwareRenderer*>(renderer_.get()) != nullptr);
  update_logging();
}

void Gpu::vblank_started() {
  if (log_words_ == 0) {
    draw_.frame_due(display_area());
  } else {  // noted where the log is now, for its replay
    log_frame_ = true;
    log_frame_at_ = log_words_;
    log_frame_area_ = display_area();
  }
  irq_.raise(Irq::VBlank);
  if (on_vblank) on_vblank();
}

const u8* Gpu::vram_rgb() {
  vram_rgb_.resize(size_t{gpu::kVramPixels} * 3);
  gpu::FrameOutput::vram_to_rgb(vram(), vram_rgb_.data());
  return vram_rgb_.data();
}

// Converts the display area as VRAM holds it now (a program may have drawn since the last VBlank).
bool Gpu::write_display_png(const std::string& path, std::string& error) const {
  settle_log();
  draw_.flush();
  gpu::FrameOutput now;
  now.refresh(*renderer_, display_area());
  return write_png_rgb(path, now.rgb(), now.width(), now.height(), error);
}

bool Gpu::write_vram_png(const std::string& path, std::string& error) {
  return write_png_rgb(path, vram_rgb(), gpu::kVramWidth, gpu::kVramHeight, error);
}

void Gpu::do_state(StateIO& s) {
  // Version 2 saves the polyline vertex field by field; version 1 saved the struct whole, with
  // its padding bytes, which made equal consoles give unequal states. Version 3 adds the CLUT
  // cache (older states load with it empty, to be reloaded by the next CLUT primitive), version
  // 4 the drawing in progress (gp0_draw_time.cpp).
  const u32 version = s.section("GPU ", 4, 1);
  // A state holds what eager drawing would have: everything drawn, the last VBlank's picture.
  if (s.loading()) {
    drop_log();
    draw_.drop();
  } else {
    replay_log();
    draw_.frame_ready();
  }
  // VRAM goes straight between the state and the renderer where it can (no 1 MiB copy; it was
  // most of a snapshot restore). Saving only reads through the pointer.
  constexpr size_t kVramBytes = size_t{gpu::kVramPixels} * sizeof(u16);
  // expect_vram() speaks for this load only, whichever way it goes.
  std::shared_ptr<const void> expected = s.loading() ? std::exchange(expected_vram_, nullptr) : nullptr;
  if (!s.loading()) {
    s.bytes(const_cast<u16*>(renderer_->vram()), kVramBytes);
  } else if (u16* direct = renderer_->vram_in_place()) {
    // A snapshot of VRAM as it still is (vram_token()) needs no copy. Only where VRAM is the
    // renderer's own memory: a scaled one holds more than the state would give back.
    if (expected && expected == vram_token_ && draw_.executed() == token_draws_) s.skip(kVramBytes);
    else s.bytes(direct, kVramBytes);
    vram_token_ = std::move(expected);
    token_draws_ = draw_.executed();
  } else {
    std::vector<u16> vram(gpu::kVramPixels);
    s.bytes(vram.data(), kVramBytes);
    renderer_->load_vram(vram.data());
    vram_token_ = nullptr;
  }
  s.pod(gp0_mode_);
  if (s.loading() && gp0_mode_ > Gp0Mode::CpuToVram) s.fail("bad GP0 mode");
  if (s.loading()) {
    s.pod(fifo_);
  } else {  // the words queued, the rest zero: words left from earlier commands are not state
    u32 queued[16] = {};
    std::copy_n(fifo_, fifo_len_, queued);
    s.pod(queued);
  }
  s.pod(fifo_len_);
  s.pod(fifo_needed_);
  if (s.loading() && (fifo_len_ > 16 || fifo_needed_ > 16)) s.fail("GP0 FIFO length out of range");
  if (version >= 2) {
    gpu::Vertex& p = polyline_last_;
    s.pod(p.x), s.pod(p.y), s.pod(p.r), s.pod(p.g), s.pod(p.b), s.pod(p.u), s.pod(p.v);
  } else {
    s.pod(polyline_last_);
  }
  s.pod(polyline_colour_);
  s.boolean(polyline_shaded_);
  s.boolean(polyline_semi_);
  s.boolean(polyline_have_colour_);
  for (Transfer* t : {&upload_, &download_}) {
    for (u32* f : {&t->x, &t->y, &t->width, &t->height, &t->col, &t->row}) s.pod(*f);
    s.boolean(t->active);
  }
  s.pod(gpuread_latch_);
  if (version >= 3) {
    s.pod(clut_tag_);
    s.boolean(clut_wide_);
    u16 entries[gpu::Renderer::kClutEntries];
    std::copy_n(renderer_->clut_cache(), gpu::Renderer::kClutEntries, entries);
    s.pod(entries);
    if (s.loading()) renderer_->set_clut_cache(entries);
  } else {
    clut_tag_ = kNoClut;
  }
  s.pod_since(version, 4, busy_until_, Cycles{0});
  s.pod_since(version, 4, fifo_empty_at_, Cycles{0});
  for (u32* r : {&draw_mode_, &texture_window_, &area_top_left_, &area_bottom_right_, &draw_offset_, &mask_bits_})
    s.pod(*r);
  s.boolean(irq_flag_);
  s.boolean(display_disabled_);
  s.pod(dma_direction_);
  dma_direction_ &= 3;
  s.pod(display_start_);
  s.pod(horizontal_range_);
  s.pod(vertical_range_);
  s.pod(display_mode_);
  s.boolean(texture_disable_allowed_);
  timing_.do_state(s);
  output_.do_state(s);
  if (s.loading()) update_draw_state();
  s.end_section("GPU ");
}

}  // namespace psx
