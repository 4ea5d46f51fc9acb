// The hardware-exact software rasterizer: owns VRAM and draws triangles, lines, rectangles,
// fills, copies and transfer rows with the rules of psx-spx "GPU Rendering". Triangles are in
// software_renderer_triangle.cpp, lines and rectangles in software_renderer_prims.cpp, VRAM
// block operations in software_renderer.cpp.
#pragma once
#include <vector>

#include "gpu/renderer.h"
#include "gpu/vram.h"

namespace psx::gpu {

class SoftwareRenderer final : public Renderer {
 public:
  SoftwareRenderer() : vram_(kVramPixels, 0) {}

  void draw_triangle(const Triangle& t, const DrawState& ds) override;
  void draw_line(const Line& l, const DrawState& ds) override;
  void draw_rectangle(const Rectangle& r, const DrawState& ds) override;
  void fill(u32 x, u32 y, u32 width, u32 height, u16 pixel) override;
  void copy(u32 src_x, u32 src_y, u32 dst_x, u32 dst_y, u32 width, u32 height, MaskMode m) override;
  void write_row(u32 x, u32 y, const u16* pixels, u32 count, MaskMode m) override;
  void load_clut(u32 x, u32 y, u32 count) override;

  const u16* vram() const override { return vram_.data(); }
  void load_vram(const u16* pixels) override;
  u16* vram_in_place() override { return vram_.data(); }

 private:
  template <int kTex, bool kRaw, bool kSemi, bool kShaded>
  void rasterize_triangle(const Triangle& t, const DrawState& ds);
  template <int kTex, bool kRaw>
  void triangle_modes(const Triangle& t, const DrawState& ds);
  template <int kTex, bool kRaw, bool kSemi>
  void rasterize_rectangle(const Rectangle& r, const DrawState& ds);
  template <bool kSemi, bool kShaded>
  void rasterize_line(const Line& l, const DrawState& ds);

  std::vector<u16> vram_;
  // One row for GP0(80): the source row is read whole before it is written (no allocation per copy).
  u16 row_buffer_[kVramWidth] = {};
};

}  // namespace psx::gpu
