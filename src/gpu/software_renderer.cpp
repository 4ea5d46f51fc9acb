// Software rasterizer: the VRAM block operations (fill, VRAM->VRAM copy, CPU->VRAM rows) and
// the CLUT cache's load.
#include "gpu/software_renderer.h"

#include <algorithm>
#include <cstring>

namespace psx::gpu {

void SoftwareRenderer::load_vram(const u16* pixels) { std::memcpy(vram_.data(), pixels, kVramPixels * sizeof(u16)); }

// GP0(02) ignores the drawing area and both mask settings and wraps at the VRAM edges.
void SoftwareRenderer::fill(u32 x, u32 y, u32 width, u32 height, u16 pixel) {
  // A row is at most two runs, split where it wraps: plain fills the compiler makes wide.
  x &= kVramWidth - 1;
  width = std::min(width, kVramWidth);
  const u32 first = std::min(width, kVramWidth - x);
  for (u32 row = 0; row < height; ++row) {
    u16* line = &vram_[((y + row) & (kVramHeight - 1)) * kVramWidth];
    std::fill_n(line + x, first, pixel);
    std::fill_n(line, width - first, pixel);
  }
}

static inline void store_masked(u16& dst, u16 src, MaskMode m) {
  if (m.check && (dst & kMaskBit)) return;
  dst = src | (m.set ? kMaskBit : 0);
}

// GP0(80) copies row by row, top to bottom; each source row is read whole before it is written,
// so overlapping copies within a row behave like memmove, and a destination below an overlapping
// source sees rows already copied (the hardware works through the rectangle in that order too).
void SoftwareRenderer::copy(u32 src_x, u32 src_y, u32 dst_x, u32 dst_y, u32 width, u32 height, MaskMode m) {
  for (u32 row = 0; row < height; ++row) {
    const u16* s = &vram_[((src_y + row) & (kVramHeight - 1)) * kVramWidth];
    u16* d = &vram_[((dst_y + row) & (kVramHeight - 1)) * kVramWidth];
    for (u32 col = 0; col < width; ++col) row_buffer_[col] = s[(src_x + col) & (kVramWidth - 1)];
    for (u32 col = 0; col < width; ++col) store_masked(d[(dst_x + col) & (kVramWidth - 1)], row_buffer_[col], m);
  }
}

void SoftwareRenderer::write_row(u32 x, u32 y, const u16* pixels, u32 count, MaskMode m) {
  u16* d = &vram_[(y & (kVramHeight - 1)) * kVramWidth];
  for (u32 i = 0; i < count; ++i) store_masked(d[(x + i) & (kVramWidth - 1)], pixels[i], m);
}

void SoftwareRenderer::load_clut(u32 x, u32 y, u32 count) {
  const u16* row = &vram_[(y & (kVramHeight - 1)) * kVramWidth];
  for (u32 i = 0; i < count; ++i) clut_[i] = row[(x + i) & (kVramWidth - 1)];
}

}  // namespace psx::gpu
