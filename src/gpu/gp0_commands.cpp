// GP0 command processing (psx-spx "GPU Render Polygon/Line/Rectangle Commands", "GPU Memory
// Transfer Commands", "GPU Rendering Attributes", "GPU Misc Commands"): words are queued until a
// command is complete, then decoded into primitives for the renderer.
#include <algorithm>

#include "gpu/gpu.h"
#include "gpu/vram.h"

namespace psx {
namespace {

inline s32 sign_extend11(u32 v) { return static_cast<s32>(v << 21) >> 21; }

// GP0(80)/(A0)/(C0) sizes: 0 means the maximum, so ((n - 1) AND mask) + 1 (psx-spx).
inline u32 transfer_width(u32 wh) { return ((wh - 1) & 0x3FF) + 1; }
inline u32 transfer_height(u32 wh) { return (((wh >> 16) - 1) & 0x1FF) + 1; }

inline void set_colour(gpu::Vertex& v, u32 colour) {
  v.r = static_cast<u8>(colour), v.g = static_cast<u8>(colour >> 8), v.b = static_cast<u8>(colour >> 16);
}

// Words per command, including the command word. Polylines are counted up to their first
// segment; the rest streams through gp0_polyline_word.
constexpr u32 command_length(u32 c) {
  switch (c >> 5) {
    case 1: {  // polygon: vertex (+ texcoord) per corner, + colour per corner after the first when shaded
      u32 corners = (c & 0x08) ? 4 : 3;
      return 1 + corners * ((c & 0x04) ? 2 : 1) + ((c & 0x10) ? corners - 1 : 0);
    }
    case 2: return (c & 0x10) ? 4 : 3;                                                    // line
    case 3: return 2 + ((c & 0x04) ? 1 : 0) + (((c >> 3) & 3) == 0 ? 1 : 0);              // rectangle
    case 4: return 4;                                                                     // VRAM->VRAM
    case 5:
    case 6: return 3;                                                                     // CPU<->VRAM
    default: return c == 0x02 ? 3 : 1;
  }
}

}  // namespace

const std::array<u8, 256> Gpu::kGp0Lengths = [] {
  std::array<u8, 256> t{};
  for (u32 c = 0; c < 256; ++c) t[c] = static_cast<u8>(command_length(c));
  return t;
}();

void Gpu::gp0_write(u32 word) {
  if (gp0_mode_ == Gp0Mode::CpuToVram) {
    const u16 pixels[2] = {static_cast<u16>(word), static_cast<u16>(word >> 16)};
    upload_pixels(pixels, 2);
    return;
  }
  if (gp0_mode_ == Gp0Mode::Polyline) {
    gp0_polyline_word(word);
    return;
  }
  if (fifo_len_ == 0) fifo_needed_ = gp0_command_length(word >> 24);
  fifo_[fifo_len_++] = word;
  if (fifo_len_ < fifo_needed_) return;
  fifo_len_ = 0;
  book_drawing(draw_time(fifo_));  // on arrival: a replayed draw log books nothing again
  gp0_execute(fifo_);
}

void Gpu::gp0_execute(const u32* w) {
  if (logging_ && log_command(w)) return;
  const u32 c = w[0] >> 24;
  switch (c >> 5) {
    case 1: return gp0_polygon(w);
    case 2: return gp0_line(w);
    case 3: return gp0_rectangle(w);
    case 4: return gp0_copy_rectangle(w);
    case 5: return gp0_copy_to_vram(w);
    case 6: return gp0_copy_from_vram(w);
    default: break;
  }
  switch (c) {
    case 0x01: return clear_cache();
    case 0x02: return gp0_fill_rectangle(w);
    case 0x1F: return gp0_irq();
    case 0xE1: case 0xE2: case 0xE3: case 0xE4: case 0xE5: case 0xE6: return gp0_environment(w[0]);
    // 00h NOP, 03h-1Eh and E0h/E7h-FFh: no effect.
    default: return;
  }
}

// Sets v's position in place (filling a vertex field by field and then copying it whole would
// read back the fresh stores at another width, which store forwarding cannot serve).
void Gpu::set_position(gpu::Vertex& v, u32 xy) const {
  // Vertex coordinates are 11-bit signed (-1024..+1023); the drawing offset is added to them.
  v.x = sign_extend11(xy) + offset_x_;
  v.y = sign_extend11(xy >> 16) + offset_y_;
}

// GP0(20)-(3F): bit 4 Gouraud, 3 quad, 2 textured, 1 semi-transparent, 0 raw texture.
void Gpu::gp0_polygon(const u32* w) {
  const u32 c = w[0] >> 24;
  const bool shaded = c & 0x10, textured = c & 0x04;
  const u32 corners = (c & 0x08) ? 4 : 3;
  gpu::Vertex v[4];
  u32 clut = 0, texpage = 0, i = 1;
  for (u32 k = 0; k < corners; ++k) {
    u32 colour = (shaded && k > 0) ? w[i++] : w[0];
    set_position(v[k], w[i++]);
    set_colour(v[k], colour);
    if (!textured) continue;
    u32 uv = w[i++];
    v[k].u = static_cast<u8>(uv), v[k].v = static_cast<u8>(uv >> 8);
    if (k == 0) clut = uv >> 16;
    if (k == 1) texpage = uv >> 16;
  }
  if (textured) apply_texpage(texpage);
  gpu::Triangle t;
  t.clut_x = static_cast<u16>((clut & 0x3F) * 16);
  t.clut_y = static_cast<u16>((clut >> 6) & 0x1FF);
  t.shaded = shaded, t.textured = textured, t.semi = c & 0x02, t.raw = c & 0x01;
  t.v[0] = v[0], t.v[1] = v[1], t.v[2] = v[2];
  const u16 load = textured ? clut_load(clut) : 0;
  if (corners == 4) draw_.quad({t, v[3]}, draw_state(), load);
  else draw_.triangle(t, draw_state(), load);
}

// A textured polygon's texpage attribute replaces GP0(E1) bits 0-8 and 11.
void Gpu::apply_texpage(u32 texpage) {
  const u32 mask = texture_disable_allowed_ ? 0x9FF : 0x1FF;
  const u32 mode = (draw_mode_ & ~mask) | (texpage & mask);
  if (mode != draw_mode_) {  // most polygons repeat the texpage in force
    draw_mode_ = mode;
    update_draw_state();
  }
}

// GP0(40)-(5F): bit 4 Gouraud, 3 polyline, 1 semi-transparent.
void Gpu::gp0_line(const u32* w) {
  const u32 c = w[0] >> 24;
  gpu::Line l;
  l.shaded = c & 0x10, l.semi = c & 0x02;
  set_position(l.v[0], w[1]);
  set_colour(l.v[0], w[0]);
  set_position(l.v[1], w[l.shaded ? 3 : 2]);
  set_colour(l.v[1], w[l.shaded ? 2 : 0]);
  draw_.line(l, draw_state());
  if (!(c & 0x08)) return;
  gp0_mode_ = Gp0Mode::Polyline;
  polyline_last_ = l.v[1];
  polyline_colour_ = w[0];
  polyline_shaded_ = l.shaded, polyline_semi_ = l.semi, polyline_have_colour_ = false;
}

// Further polyline vertices ([colour,] vertex) until a 5xxx5xxx word where a vertex would start.
void Gpu::gp0_polyline_word(u32 word) {
  const bool vertex_start = !polyline_shaded_ || !polyline_have_colour_;
  if (vertex_start && (word & 0xF000F000) == 0x50005000) {
    gp0_mode_ = Gp0Mode::Command;
    return;
  }
  if (polyline_shaded_ && !polyline_have_colour_) {
    polyline_colour_ = word;
    polyline_have_colour_ = true;
    return;
  }
  polyline_have_colour_ = false;
  gpu::Line l;
  l.shaded = polyline_shaded_, l.semi = polyline_semi_;
  l.v[0] = polyline_last_;
  set_position(l.v[1], word);
  set_colour(l.v[1], polyline_colour_);
  book_line(l.v[0], l.v[1]);
  draw_.line(l, draw_state());
  polyline_last_ = l.v[1];
}

// GP0(60)-(7F): bits 3-4 size (variable, 1x1, 8x8, 16x16), 2 textured, 1 semi, 0 raw.
void Gpu::gp0_rectangle(const u32* w) {
  const u32 c = w[0] >> 24;
  gpu::Rectangle r;
  gpu::Vertex p;
  set_position(p, w[1]);
  r.x = p.x, r.y = p.y;
  r.r = static_cast<u8>(w[0]), r.g = static_cast<u8>(w[0] >> 8), r.b = static_cast<u8>(w[0] >> 16);
  r.textured = c & 0x04, r.semi = c & 0x02, r.raw = c & 0x01;
  u32 i = 2;
  u16 load = 0;
  if (r.textured) {
    u32 uv = w[i++];
    load = clut_load(uv >> 16);
    r.u = static_cast<u8>(uv), r.v = static_cast<u8>(uv >> 8);
    r.clut_x = static_cast<u16>(((uv >> 16) & 0x3F) * 16);
    r.clut_y = static_cast<u16>((uv >> 22) & 0x1FF);
  }
  static constexpr u32 kSizes[4] = {0, 1, 8, 16};
  const u32 size = (c >> 3) & 3;
  if (size == 0) {
    r.width = w[i] & 0x3FF, r.height = (w[i] >> 16) & 0x1FF;
  } else {
    r.width = r.height = kSizes[size];
  }
  draw_.rectangle(r, draw_state(), load);
}

// The CLUT cache entries a textured primitive with CLUT attribute `clut` (a polygon's or
// rectangle's texcoord word, bits 16-31) loads before drawing: 16 (4-bit texels) or 256 (8-bit)
// when the cache holds another CLUT, or only 16 entries where 256 are needed; 0 for 15-bit
// texels and when the cache already holds what is needed. The hardware capture of ps1-tests
// gpu/clut-cache shows each case (a palette rewritten in VRAM is not seen until a reload; a
// change of texture depth by GP0(E1) alone reloads nothing); DuckStation's
// GPU::UpdateCLUTIfNeeded keeps the same rule.
u16 Gpu::clut_load(u32 clut) {
  if (ds_.texture_disable || ds_.tex_depth >= 2) return 0;
  const u32 position = clut & 0x7FFF;  // bit 15 is not part of the attribute
  const bool wide = ds_.tex_depth == 1;
  if (position == clut_tag_ && (clut_wide_ || !wide)) return 0;
  clut_tag_ = position, clut_wide_ = wide;
  return wide ? 256 : 16;
}

// GP0(01) clears the texture cache, the CLUT cache with it: the next CLUT primitive reloads
// (psx-spx "GP0(01h) - Clear Cache").
void Gpu::clear_cache() { clut_tag_ = kNoClut; }

// GP0(02): X rounded down and width rounded up to 16 pixels; Y and height as given (9 bits).
void Gpu::gp0_fill_rectangle(const u32* w) {
  const u32 xy = w[1], wh = w[2];
  const u32 x = xy & 0x3F0, y = (xy >> 16) & 0x1FF;
  const u32 width = ((wh & 0x3FF) + 0xF) & ~0xFu, height = (wh >> 16) & 0x1FF;
  draw_.fill(x, y, width, height, gpu::rgb24_to_15(w[0]));
}

void Gpu::gp0_copy_rectangle(const u32* w) {
  const u32 src = w[1], dst = w[2], wh = w[3];
  gpu::MaskMode m{(mask_bits_ & 1) != 0, (mask_bits_ & 2) != 0};
  draw_.copy(src & 0x3FF, (src >> 16) & 0x1FF, dst & 0x3FF, (dst >> 16) & 0x1FF, transfer_width(wh),
                  transfer_height(wh), m);
}

void Gpu::gp0_copy_to_vram(const u32* w) {
  upload_ = Transfer{w[1] & 0x3FF, (w[1] >> 16) & 0x1FF, transfer_width(w[2]),
                     transfer_height(w[2]), 0, 0, true};
  gp0_mode_ = Gp0Mode::CpuToVram;
}

void Gpu::gp0_copy_from_vram(const u32* w) {
  download_ = Transfer{w[1] & 0x3FF, (w[1] >> 16) & 0x1FF, transfer_width(w[2]),
                       transfer_height(w[2]), 0, 0, true};
}

// Pixels of a GP0(A0) transfer, row by row with wrap; E6 mask settings apply. Pixels past the
// end (the unused half of an odd-sized transfer's last word) are dropped.
void Gpu::upload_pixels(const u16* pixels, u32 count) {
  const gpu::MaskMode m{(mask_bits_ & 1) != 0, (mask_bits_ & 2) != 0};
  u32 i = 0;
  while (i < count && upload_.active) {
    u32 take = std::min(count - i, upload_.width - upload_.col);
    draw_.write_row(upload_.x + upload_.col, upload_.y + upload_.row, pixels + i, take, m);
    i += take;
    upload_.col += take;
    if (upload_.col < upload_.width) continue;
    upload_.col = 0;
    if (++upload_.row == upload_.height) {
      upload_.active = false;
      gp0_mode_ = Gp0Mode::Command;
    }
  }
}

// GP0(E1)-(E6), the drawing environment.
void Gpu::gp0_environment(u32 word) {
  switch (word >> 24) {
    case 0xE1: return gp0_draw_mode(word);
    case 0xE2: return gp0_texture_window(word);
    case 0xE3: return gp0_draw_area_top_left(word);
    case 0xE4: return gp0_draw_area_bottom_right(word);
    case 0xE5: return gp0_draw_offset(word);
    default: return gp0_mask_bit(word);
  }
}

void Gpu::gp0_draw_mode(u32 word) {
  draw_mode_ = word & (texture_disable_allowed_ ? 0x3FFF : 0x37FF);
  update_draw_state();
}

void Gpu::gp0_texture_window(u32 word) {
  texture_window_ = word & 0xFFFFF;
  update_draw_state();
}

void Gpu::gp0_draw_area_top_left(u32 word) {
  area_top_left_ = word & 0x7FFFF;
  update_draw_state();
}

void Gpu::gp0_draw_area_bottom_right(u32 word) {
  area_bottom_right_ = word & 0x7FFFF;
  update_draw_state();
}

void Gpu::gp0_draw_offset(u32 word) {
  draw_offset_ = word & 0x3FFFFF;
  update_draw_state();
}

void Gpu::gp0_mask_bit(u32 word) {
  mask_bits_ = word & 3;
  update_draw_state();
}

// GP0(1F): sets GPUSTAT.24 and raises the GPU interrupt until GP1(02) acknowledges it.
void Gpu::gp0_irq() {
  irq_flag_ = true;
  irq_.raise(Irq::Gpu);
}

// Decodes the raw E1-E6 registers into the renderer's DrawState.
void Gpu::update_draw_state() {
  ds_.texpage_x = static_cast<u16>((draw_mode_ & 0xF) * 64);
  ds_.texpage_y = static_cast<u16>(((draw_mode_ >> 4) & 1) * 256);
  ds_.semi_mode = static_cast<u8>((draw_mode_ >> 5) & 3);
  ds_.tex_depth = static_cast<u8>((draw_mode_ >> 7) & 3);
  ds_.dither = draw_mode_ & 0x200;
  ds_.texture_disable = draw_mode_ & 0x800;
  ds_.flip_x = draw_mode_ & 0x1000;
  ds_.flip_y = draw_mode_ & 0x2000;
  const u32 mask_u = texture_window_ & 0x1F, mask_v = (texture_window_ >> 5) & 0x1F;
  const u32 off_u = (texture_window_ >> 10) & 0x1F, off_v = (texture_window_ >> 15) & 0x1F;
  ds_.win_and_u = static_cast<u8>(~(mask_u * 8)), ds_.win_or_u = static_cast<u8>((off_u & mask_u) * 8);
  ds_.win_and_v = static_cast<u8>(~(mask_v * 8)), ds_.win_or_v = static_cast<u8>((off_v & mask_v) * 8);
  ds_.area_left = static_cast<s32>(area_top_left_ & 0x3FF);
  ds_.area_top = static_cast<s32>((area_top_left_ >> 10) & 0x1FF);
  ds_.area_right = static_cast<s32>(area_bottom_right_ & 0x3FF);
  ds_.area_bottom = static_cast<s32>((area_bottom_right_ >> 10) & 0x1FF);
  offset_x_ = sign_extend11(draw_offset_);
  offset_y_ = sign_extend11(draw_offset_ >> 11);
  time_area_ = {ds_.area_left - offset_x_, ds_.area_top - offset_y_, ds_.area_right + 1 - offset_x_,
                ds_.area_bottom + 1 - offset_y_};
  ds_.set_mask = mask_bits_ & 1;
  ds_.check_mask = mask_bits_ & 2;
}

// The environment for the next primitive. In 480-line interlace without GP0(E1).10 the GPU
// leaves alone the rows of the field being displayed.
const gpu::DrawState& Gpu::draw_state() {
  const bool interlace480 = (display_mode_ & 0x24) == 0x24;
  ds_.skip_row_parity = (interlace480 && !(draw_mode_ & 0x400)) ? (timing_.odd_field() ? 1 : 0) : -1;
  return ds_;
}

}  // namespace psx
