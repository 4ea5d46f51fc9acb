// OpenGL renderer: set-up, the record batch and the snapshot bookkeeping (gl_renderer.h).
#include "gpu/gl/gl_renderer.h"

#include <algorithm>
#include <stdexcept>

#include "gpu/gl/osmesa_context.h"
#include "gpu/vram.h"

namespace psx::gpu::gl {

namespace {
constexpr s32 kCell = 16;                  // stale-grid cell size in native pixels
constexpr size_t kMaxBatch = 8192;         // records per draw call
}  // namespace

std::unique_ptr<GlRenderer> GlRenderer::create(std::unique_ptr<GlContext> context, u32 scale, std::string& error) {
  if (scale < 1 || scale > kMaxScale) {
    error = "scale " + std::to_string(scale) + " is outside 1 to " + std::to_string(kMaxScale);
    return nullptr;
  }
  std::unique_ptr<GlRenderer> r(new GlRenderer(std::move(context), scale));
  if (!r->init(error)) return nullptr;
  return r;
}

std::unique_ptr<Renderer> make_osmesa_renderer(u32 scale, const std::string& library, std::string& error) {
  std::unique_ptr<OsMesaContext> context = OsMesaContext::create(library, error);
  if (!context) return nullptr;
  return GlRenderer::create(std::move(context), scale, error);
}

bool GlRenderer::init(std::string& error) {
  context_->make_current();
  if (!gl_.load(*context_, error)) return false;
  GLint major = 0, minor = 0;
  gl_.GetIntegerv(GL_MAJOR_VERSION, &major);
  gl_.GetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 33) {
    error = context_->name() + " gives OpenGL " + std::to_string(major) + "." + std::to_string(minor) +
            ", the renderer needs 3.3";
    return false;
  }
  if (!build_programs(gl_, programs_, error)) return false;
  // One variant now, so that a compiler problem is reported here rather than at the first draw.
  if (!draw_variant(gl_, 0, scale_, variants_[0], error)) return false;

  const GLsizei w = static_cast<GLsizei>(kVramWidth * scale_), h = static_cast<GLsizei>(kVramHeight * scale_);
  auto texture = [&](GLuint& tex, GLsizei tw, GLsizei th) {
    gl_.GenTextures(1, &tex);
    gl_.BindTexture(GL_TEXTURE_2D, tex);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_R16UI, tw, th, 0, GL_RED_INTEGER, GL_UNSIGNED_SHORT, nullptr);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  };
  auto framebuffer = [&](GLuint& fbo, GLuint tex) {
    gl_.GenFramebuffers(1, &fbo);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    return gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
  };
  texture(vram_tex_, w, h);
  texture(snapshot_tex_, w, h);
  texture(staging_tex_, kVramWidth, kVramHeight);
  texture(native_tex_, kVramWidth, kVramHeight);
  texture(palette_tex_, kClutEntries, 1);
  gl_.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kClutEntries, 1, GL_RED_INTEGER, GL_UNSIGNED_SHORT, palette_);
  if (!framebuffer(vram_fbo_, vram_tex_) || !framebuffer(snapshot_fbo_, snapshot_tex_) ||
      !framebuffer(native_fbo_, native_tex_)) {
    error = context_->name() + " cannot render to 16-bit integer textures";
    return false;
  }
  const GLuint zero[4] = {0, 0, 0, 0};
  for (GLuint fbo : {vram_fbo_, snapshot_fbo_}) {
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl_.ClearBufferuiv(GL_COLOR, 0, zero);
  }

  gl_.GenVertexArrays(1, &vao_);
  gl_.BindVertexArray(vao_);
  gl_.GenBuffers(1, &vbo_);
  gl_.BindBuffer(GL_ARRAY_BUFFER, vbo_);
  for (GLuint i = 0; i < kRecordVec4s; ++i) {
    gl_.EnableVertexAttribArray(i);
    gl_.VertexAttribIPointer(i, 4, GL_INT, sizeof(PrimitiveRecord), reinterpret_cast<const void*>(size_t{i} * 16));
    gl_.VertexAttribDivisor(i, 1);
  }
  gl_.Disable(GL_DITHER);
  gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  staging_row_used_.assign(kVramHeight, false);
  native_.assign(kVramPixels, 0);
  native_valid_ = true;
  if (GLenum e = gl_.GetError(); e != GL_NO_ERROR) {
    error = context_->name() + " reported OpenGL error " + std::to_string(e) + " during set-up";
    return false;
  }
  return true;
}

GlRenderer::~GlRenderer() {
  if (!vao_) return;
  context_->make_current();
  gl_.DeleteBuffers(1, &vbo_);
  gl_.DeleteVertexArrays(1, &vao_);
  GLuint fbos[3] = {vram_fbo_, snapshot_fbo_, native_fbo_};
  gl_.DeleteFramebuffers(3, fbos);
  GLuint textures[5] = {vram_tex_, snapshot_tex_, staging_tex_, native_tex_, palette_tex_};
  gl_.DeleteTextures(5, textures);
  for (const DrawProgram& p : variants_)
    if (p.program) gl_.DeleteProgram(p.program);
  gl_.DeleteProgram(programs_.downsample);
}

// Calls fn for the pieces of a rectangle that may run past VRAM's right or bottom edge.
template <typename Fn>
static void for_each_wrapped(s32 x, s32 y, s32 w, s32 h, Fn fn) {
  const s32 W = kVramWidth, H = kVramHeight;
  x &= W - 1, y &= H - 1;
  w = std::min(w, W), h = std::min(h, H);
  for (s32 ys = y; ys < y + h; ys = (ys / H + 1) * H)
    for (s32 xs = x; xs < x + w; xs = (xs / W + 1) * W) {
      s32 xe = std::min(x + w, (xs / W + 1) * W), ye = std::min(y + h, (ys / H + 1) * H);
      fn(xs % W, ys % H, xe - xs, ye - ys);
    }
}

// The stale-grid bits of the cell columns a rectangle touches.
static u64 cell_columns(const Rect& r) {
  const s32 cx0 = r.x0 / kCell, cx1 = (r.x1 - 1) / kCell;
  return (cx1 - cx0 == 63 ? ~u64{0} : ((u64{1} << (cx1 - cx0 + 1)) - 1)) << cx0;
}

void GlRenderer::mark_stale(const Rect& r) {
  const u64 bits = cell_columns(r);
  for (s32 cy = r.y0 / kCell; cy <= (r.y1 - 1) / kCell; ++cy) stale_[cy] |= bits;
}

bool GlRenderer::any_stale(const Rect& r) const {
  const u64 bits = cell_columns(r);
  for (s32 cy = r.y0 / kCell; cy <= (r.y1 - 1) / kCell; ++cy)
    if (stale_[cy] & bits) return true;
  return false;
}

// Copies the stale cells' rows of `area` (cell-aligned) from VRAM to the snapshot.
void GlRenderer::sync(const Rect& area) {
  if (!any_stale(area)) return;
  flush();
  const s32 cx0 = area.x0 / kCell, cx1 = (area.x1 - 1) / kCell;
  const u64 bits = cell_columns(area);
  const s32 n = static_cast<s32>(scale_);
  const s32 x0 = cx0 * kCell * n, x1 = (cx1 + 1) * kCell * n;
  const s32 y0 = (area.y0 / kCell) * kCell * n, y1 = ((area.y1 - 1) / kCell + 1) * kCell * n;
  gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, vram_fbo_);
  gl_.BindFramebuffer(GL_DRAW_FRAMEBUFFER, snapshot_fbo_);
  gl_.BlitFramebuffer(x0, y0, x1, y1, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  for (s32 cy = area.y0 / kCell; cy <= (area.y1 - 1) / kCell; ++cy) stale_[cy] &= ~bits;
}

void GlRenderer::sync_reads(const Rect* reads, u32 read_count) {
  context_->make_current();
  for (u32 i = 0; i < read_count; ++i) {
    const Rect& a = reads[i];
    for_each_wrapped(a.x0, a.y0, a.x1 - a.x0, a.y1 - a.y0,
                     [&](s32 x, s32 y, s32 w, s32 h) { sync({x, y, x + w, y + h}); });
  }
}

void GlRenderer::push(const PrimitiveRecord& r) {
  const u32 variant = variant_of(r.flags);
  if (runs_.empty() || runs_.back().second != variant) runs_.emplace_back(static_cast<u32>(batch_.size()), variant);
  batch_.push_back(r);
  mark_stale({r.bbox[0], r.bbox[1], r.bbox[2], r.bbox[3]});
  native_valid_ = false;
  if (batch_.size() >= kMaxBatch) flush();
}

const DrawProgram& GlRenderer::program(u32 variant) const {
  DrawProgram& p = variants_[variant];
  if (!p.program) {
    std::string error;
    // Every variant is the same source with other constants, and variant 0 compiled at set-up.
    if (!draw_variant(gl_, variant, scale_, p, error)) throw std::runtime_error("OpenGL renderer: " + error);
  }
  return p;
}

// Draws the batch: one instanced draw per run, the records' attributes pointed at the run.
void GlRenderer::flush() const {
  if (batch_.empty()) return;
  context_->make_current();
  const GlFunctions& gl = gl_;
  gl.BindFramebuffer(GL_FRAMEBUFFER, vram_fbo_);
  gl.Viewport(0, 0, static_cast<GLsizei>(kVramWidth * scale_), static_cast<GLsizei>(kVramHeight * scale_));
  gl.ActiveTexture(GL_TEXTURE2);
  gl.BindTexture(GL_TEXTURE_2D, palette_tex_);
  gl.ActiveTexture(GL_TEXTURE1);
  gl.BindTexture(GL_TEXTURE_2D, staging_tex_);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_2D, snapshot_tex_);
  gl.BindVertexArray(vao_);
  gl.BindBuffer(GL_ARRAY_BUFFER, vbo_);
  gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(batch_.size() * sizeof(PrimitiveRecord)), batch_.data(),
                GL_STREAM_DRAW);
  for (size_t i = 0; i < runs_.size(); ++i) {
    const auto [first, variant] = runs_[i];
    const u32 end = i + 1 < runs_.size() ? runs_[i + 1].first : static_cast<u32>(batch_.size());
    const DrawProgram& p = program(variant);
    gl.UseProgram(p.program);
    for (GLuint a = 0; a < kRecordVec4s; ++a)
      gl.VertexAttribIPointer(a, 4, GL_INT, sizeof(PrimitiveRecord),
                              reinterpret_cast<const void*>(size_t{first} * sizeof(PrimitiveRecord) + size_t{a} * 16));
    gl.DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(end - first));
  }
  batch_.clear();
  runs_.clear();
  std::fill(staging_row_used_.begin(), staging_row_used_.end(), false);
}

}  // namespace psx::gpu::gl
