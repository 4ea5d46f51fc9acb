// OpenGL renderer: VRAM block operations and transfers. Fills are clears; VRAM copies and CPU
// rows are records like primitives (so they batch and obey the same read/write ordering); CPU rows go
// through a native staging texture that the shader enlarges. Read-back flushes the batch and
// downloads either the scaled texture's rectangle or, for vram(), the native 1024x512 made by
// the downsample program.
#include <algorithm>
#include <cstring>

#include "gpu/gl/gl_renderer.h"
#include "gpu/vram.h"

namespace psx::gpu::gl {

namespace {
// Splits a run [start, start + length) at the wrap point `size` into at most two pieces.
template <typename Fn>
void split_wrap(u32 start, u32 length, u32 size, Fn fn) {
  start &= size - 1;
  length = std::min(length, size);
  u32 first = std::min(length, size - start);
  fn(start, first, 0u);
  if (first < length) fn(0u, length - first, first);
}

PrimitiveRecord block_record(Kind kind, MaskMode m, s32 x, s32 y, s32 w, s32 h) {
  PrimitiveRecord r{};
  u32 f = static_cast<u32>(kind);
  if (m.check) f |= flag::kCheckMask;
  if (m.set) f |= flag::kSetMask;
  r.flags = static_cast<s32>(f);
  r.bbox[0] = x, r.bbox[1] = y, r.bbox[2] = x + w, r.bbox[3] = y + h;
  return r;
}
}  // namespace

// Fills are scissored clears of the VRAM texture (llvmpipe clears far faster than it shades):
// the batch before them is drawn first.
void GlRenderer::fill(u32 x, u32 y, u32 width, u32 height, u16 pixel) {
  if (width == 0 || height == 0) return;
  flush();
  context_->make_current();
  gl_.BindFramebuffer(GL_FRAMEBUFFER, vram_fbo_);
  gl_.Enable(GL_SCISSOR_TEST);
  const GLuint value[4] = {pixel, 0, 0, 0};
  const s32 n = static_cast<s32>(scale_);
  split_wrap(y, height, kVramHeight, [&](u32 ys, u32 hs, u32) {
    split_wrap(x, width, kVramWidth, [&](u32 xs, u32 ws, u32) {
      gl_.Scissor(static_cast<GLint>(xs) * n, static_cast<GLint>(ys) * n, static_cast<GLsizei>(ws) * n,
                  static_cast<GLsizei>(hs) * n);
      gl_.ClearBufferuiv(GL_COLOR, 0, value);
      mark_stale({static_cast<s32>(xs), static_cast<s32>(ys), static_cast<s32>(xs + ws), static_cast<s32>(ys + hs)});
    });
  });
  gl_.Disable(GL_SCISSOR_TEST);
  native_valid_ = false;
}

// `rows` rows of a GP0(80) copy: reads the source (and the destination when the mask is
// checked) from the snapshot.
void GlRenderer::copy_rows(u32 src_x, u32 src_y, u32 dst_x, u32 dst_y, u32 width, u32 rows, MaskMode m) {
  // Up to four pieces where the destination wraps; all read before any is written.
  PrimitiveRecord pieces[4];
  Rect reads[8];
  u32 count = 0, read_count = 0;
  split_wrap(dst_y, rows, kVramHeight, [&](u32 ys, u32 hs, u32 row_offset) {
    split_wrap(dst_x, width, kVramWidth, [&](u32 xs, u32 ws, u32 col_offset) {
      PrimitiveRecord& r = pieces[count++];
      r = block_record(Kind::Copy, m, xs, ys, ws, hs);
      r.a[0] = src_x, r.a[1] = src_y, r.b[0] = dst_x, r.b[1] = dst_y;
      reads[read_count++] = {static_cast<s32>(src_x + col_offset), static_cast<s32>(src_y + row_offset),
                             static_cast<s32>(src_x + col_offset + ws), static_cast<s32>(src_y + row_offset + hs)};
      if (m.check) reads[read_count++] = {r.bbox[0], r.bbox[1], r.bbox[2], r.bbox[3]};
    });
  });
  sync_reads(reads, read_count);
  for (u32 i = 0; i < count; ++i) push(pieces[i]);
}

// GP0(80) works top to bottom, each source row read whole before it is written (software
// renderer): when the destination lies d rows below an overlapping source, rows copied earlier
// are read again, so the copy goes in bands of d rows, each reading what the band before wrote.
void GlRenderer::copy(u32 src_x, u32 src_y, u32 dst_x, u32 dst_y, u32 width, u32 height, MaskMode m) {
  if (width == 0 || height == 0) return;
  const u32 d = (dst_y - src_y) & (kVramHeight - 1);
  const u32 band = (d > 0 && d < height) ? d : height;
  for (u32 row = 0; row < height; row += band) {
    u32 rows = std::min(band, height - row);
    copy_rows(src_x, (src_y + row) & (kVramHeight - 1), dst_x, (dst_y + row) & (kVramHeight - 1), width, rows, m);
  }
}

void GlRenderer::write_row(u32 x, u32 y, const u16* pixels, u32 count, MaskMode m) {
  y &= kVramHeight - 1;
  if (staging_row_used_[y]) flush();
  context_->make_current();
  split_wrap(x, count, kVramWidth, [&](u32 xs, u32 ws, u32 offset) {
    // Bound for each piece: the first piece's add() may flush, which binds other textures.
    gl_.BindTexture(GL_TEXTURE_2D, staging_tex_);
    gl_.TexSubImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(xs), static_cast<GLint>(y), static_cast<GLsizei>(ws), 1,
                      GL_RED_INTEGER, GL_UNSIGNED_SHORT, pixels + offset);
    PrimitiveRecord r = block_record(Kind::Upload, m, xs, y, ws, 1);
    Rect dest{r.bbox[0], r.bbox[1], r.bbox[2], r.bbox[3]};
    add(r, &dest, m.check ? 1 : 0);
  });
  staging_row_used_[y] = true;
}

void GlRenderer::load_vram(const u16* pixels) {
  flush();
  context_->make_current();
  gl_.BindTexture(GL_TEXTURE_2D, staging_tex_);
  gl_.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kVramWidth, kVramHeight, GL_RED_INTEGER, GL_UNSIGNED_SHORT, pixels);
  add(block_record(Kind::Upload, {}, 0, 0, kVramWidth, kVramHeight), nullptr, 0);
  flush();
  std::fill(std::begin(stale_), std::end(stale_), ~u64{0});
  sync({0, 0, static_cast<s32>(kVramWidth), static_cast<s32>(kVramHeight)});
  std::memcpy(native_.data(), pixels, kVramPixels * sizeof(u16));
  native_valid_ = true;
}

const u16* GlRenderer::vram() const {
  if (native_valid_) return native_.data();
  flush();
  context_->make_current();
  const GlFunctions& gl = gl_;
  if (scale_ == 1) {
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, vram_fbo_);
  } else {
    gl.BindFramebuffer(GL_FRAMEBUFFER, native_fbo_);
    gl.Viewport(0, 0, kVramWidth, kVramHeight);
    gl.UseProgram(programs_.downsample);
    gl.Uniform1i(programs_.downsample_scale, static_cast<GLint>(scale_));
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, vram_tex_);
    gl.BindVertexArray(vao_);
    gl.DrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  gl.PixelStorei(GL_PACK_ROW_LENGTH, 0);
  gl.ReadPixels(0, 0, kVramWidth, kVramHeight, GL_RED_INTEGER, GL_UNSIGNED_SHORT, native_.data());
  native_valid_ = true;
  return native_.data();
}

void GlRenderer::read_scaled(u32 x, u32 y, u32 width, u32 height, u16* out) const {
  flush();
  context_->make_current();
  const u32 n = scale_;
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, vram_fbo_);
  gl_.PixelStorei(GL_PACK_ROW_LENGTH, static_cast<GLint>(width * n));
  split_wrap(y, height, kVramHeight, [&](u32 ys, u32 hs, u32 row_offset) {
    split_wrap(x, width, kVramWidth, [&](u32 xs, u32 ws, u32 col_offset) {
      u16* dst = out + size_t{row_offset} * n * width * n + size_t{col_offset} * n;
      gl_.ReadPixels(static_cast<GLint>(xs * n), static_cast<GLint>(ys * n), static_cast<GLsizei>(ws * n),
                     static_cast<GLsizei>(hs * n), GL_RED_INTEGER, GL_UNSIGNED_SHORT, dst);
    });
  });
  gl_.PixelStorei(GL_PACK_ROW_LENGTH, 0);
}

// The native samples (each scale x scale block's top-left) of the CLUT row.
void GlRenderer::load_clut(u32 x, u32 y, u32 count) {
  std::vector<u16> row(size_t{count} * scale_ * scale_);
  read_scaled(x, y, count, 1, row.data());
  for (u32 i = 0; i < count; ++i) clut_[i] = row[size_t{i} * scale_];
}

void GlRenderer::sync_palette() {
  if (std::equal(clut_, clut_ + kClutEntries, palette_)) return;
  flush();
  context_->make_current();
  gl_.BindTexture(GL_TEXTURE_2D, palette_tex_);
  gl_.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kClutEntries, 1, GL_RED_INTEGER, GL_UNSIGNED_SHORT, clut_);
  std::copy_n(clut_, kClutEntries, palette_);
}

}  // namespace psx::gpu::gl
