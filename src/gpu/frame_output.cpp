// Display area and VRAM conversion to RGB888.
#include "gpu/frame_output.h"

#include <algorithm>
#include <cstring>

#include "gpu/vram.h"

namespace psx::gpu {

FrameOutput::FrameOutput() : rgb_(kMaxWidth * kMaxHeight * 3, 0) {}

static inline void put15(u8* out, u16 p) {
  out[0] = expand5(p & 0x1F);
  out[1] = expand5((p >> 5) & 0x1F);
  out[2] = expand5((p >> 10) & 0x1F);
}

void FrameOutput::refresh(const u16* vram, const DisplayArea& area) {
  width_ = std::clamp<u32>(area.width, 1, kMaxWidth);
  height_ = std::clamp<u32>(area.height, 1, kMaxHeight);
  u8* out = rgb_.data();
  if (!area.enabled) {
    std::memset(out, 0, size_t{width_} * height_ * 3);
    return;
  }
  for (u32 row = 0; row < height_; ++row) {
    const u16* line = vram + ((area.y + row) & (kVramHeight - 1)) * kVramWidth;
    u8* o = out + size_t{row} * width_ * 3;
    if (!area.rgb24) {
      for (u32 col = 0; col < width_; ++col) put15(o + col * 3, line[(area.x + col) & (kVramWidth - 1)]);
      continue;
    }
    // 24-bit mode: the row is a byte stream (little-endian halfwords) starting at the display X,
    // three bytes R, G, B per pixel, wrapping at the 2048-byte VRAM row.
    u32 byte = area.x * 2;
    for (u32 col = 0; col < width_ * 3; ++col, ++byte) {
      u16 half = line[(byte >> 1) & (kVramWidth - 1)];
      o[col] = static_cast<u8>(byte & 1 ? half >> 8 : half);
    }
  }
}

void FrameOutput::vram_to_rgb(const u16* vram, u8* out) {
  for (u32 i = 0; i < kVramPixels; ++i) put15(out + i * 3, vram[i]);
}

void FrameOutput::do_state(StateIO& s) {
  s.section("GPUO", 1);
  s.pod(width_);
  s.pod(height_);
  if (s.loading() && (width_ == 0 || width_ > kMaxWidth || height_ == 0 || height_ > kMaxHeight))
    s.fail("display output size " + std::to_string(width_) + "x" + std::to_string(height_) + " out of range");
  s.bytes(rgb_.data(), size_t{width_} * height_ * 3);
  s.end_section("GPUO");
}

}  // namespace psx::gpu
