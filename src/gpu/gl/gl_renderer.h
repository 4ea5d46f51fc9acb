// The OpenGL 3.3 renderer: VRAM lives in a texture at `scale` times the native 1024x512 and every
// drawing operation is a record for one shader program (gl_shaders.h) that applies the
// PlayStation's rules per fragment. Records are batched into one instanced draw until an
// operation reads VRAM that earlier records of the batch wrote (a texture page, CLUT or the
// background of a blended or mask-checked primitive): reads see a snapshot texture, refreshed
// from the drawing texture only where it is stale (a 16x16-pixel cell grid says where).
// Primitive set-up is in gl_primitives.cpp, VRAM transfers and read-back in gl_renderer_vram.cpp.
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "gpu/gl/gl_context.h"
#include "gpu/gl/gl_functions.h"
#include "gpu/gl/gl_shaders.h"
#include "gpu/renderer.h"

namespace psx::gpu::gl {

constexpr u32 kMaxScale = 8;

// A native rectangle [x0, x1) x [y0, y1); read areas may run past the right or bottom edge (wrap).
struct Rect {
  s32 x0, y0, x1, y1;
};

class GlRenderer final : public Renderer {
 public:
  // Sets up textures and programs on `context` (made current here); null with `error` set when
  // the context lacks what the renderer needs. VRAM starts all zero.
  static std::unique_ptr<GlRenderer> create(std::unique_ptr<GlContext> context, u32 scale, std::string& error);
  ~GlRenderer() override;

  void draw_triangle(const Triangle& t, const DrawState& ds) override;
  void draw_line(const Line& l, const DrawState& ds) override;
  void draw_rectangle(const Rectangle& r, const DrawState& ds) override;
  void fill(u32 x, u32 y, u32 width, u32 height, u16 pixel) override;
  void copy(u32 src_x, u32 src_y, u32 dst_x, u32 dst_y, u32 width, u32 height, MaskMode m) override;
  void write_row(u32 x, u32 y, const u16* pixels, u32 count, MaskMode m) override;
  // The entries are read back from VRAM into the cache (clut_), from which the draw program
  // takes 4- and 8-bit texels' colours (a palette texture, sync_palette()), so a palette rewritten
  // in VRAM is not seen until the GPU reloads it, as on the console.
  void load_clut(u32 x, u32 y, u32 count) override;
  const u16* vram() const override;
  void load_vram(const u16* pixels) override;
  u32 scale() const override { return scale_; }
  void read_scaled(u32 x, u32 y, u32 width, u32 height, u16* out) const override;

 private:
  explicit GlRenderer(std::unique_ptr<GlContext> context, u32 scale) : context_(std::move(context)), scale_(scale) {}
  bool init(std::string& error);

  // Queues `r` after bringing the snapshot up to date for the areas it reads (`reads`, native
  // rectangles that may run past the right/bottom edge and wrap); marks its box stale.
  void add(const PrimitiveRecord& r, const Rect* reads, u32 read_count) {
    sync_reads(reads, read_count);
    push(r);
  }
  // The two halves, for an operation made of several records that must all read VRAM as it was
  // before any of them (the pieces of a copy that wraps at the VRAM edge).
  void sync_reads(const Rect* reads, u32 read_count);
  void push(const PrimitiveRecord& r);
  void sync(const Rect& area);
  void flush() const;
  const DrawProgram& program(u32 variant) const;
  void mark_stale(const Rect& r);
  bool any_stale(const Rect& r) const;
  void copy_rows(u32 src_x, u32 src_y, u32 dst_x, u32 dst_y, u32 width, u32 rows, MaskMode m);
  // Brings the palette texture to the CLUT cache's entries (loaded, or set by a state load or a
  // change of backend) before a 4- or 8-bit textured record is queued; records already queued
  // are drawn first, with the palette they were made with.
  void sync_palette();

  std::unique_ptr<GlContext> context_;
  GlFunctions gl_;
  Programs programs_;
  u32 scale_ = 1;
  GLuint vram_tex_ = 0, snapshot_tex_ = 0, staging_tex_ = 0, native_tex_ = 0;
  GLuint palette_tex_ = 0;  // 256 x 1: the CLUT cache as the draw program reads it
  u16 palette_[kClutEntries] = {};  // what palette_tex_ holds
  GLuint vram_fbo_ = 0, snapshot_fbo_ = 0, native_fbo_ = 0;
  GLuint vao_ = 0, vbo_ = 0;

  // Draw program variants, compiled when first needed.
  mutable DrawProgram variants_[kDrawVariants];
  // Records not yet drawn, in runs of one variant each (first record, variant), and the staging
  // rows they use (a row is re-uploaded only after them).
  mutable std::vector<PrimitiveRecord> batch_;
  mutable std::vector<std::pair<u32, u32>> runs_;
  mutable std::vector<bool> staging_row_used_;
  // Bit (cx) of stale_[cy]: the 16x16 cell (cx, cy) may differ between VRAM and the snapshot.
  u64 stale_[32] = {};
  // vram()'s answer, valid until the next change.
  mutable std::vector<u16> native_;
  mutable bool native_valid_ = false;
};

// An OSMesa-backed renderer at `scale`, with libOSMesa loaded from `library`; null with `error`
// set when OSMesa or OpenGL 3.3 is unavailable.
std::unique_ptr<Renderer> make_osmesa_renderer(u32 scale, const std::string& library, std::string& error);

}  // namespace psx::gpu::gl
