// Display area and VRAM conversion to RGB888.
#include "gpu/frame_output.h"

#include <algorithm>
#include <array>
#include <cstring>

#include "gpu/vram.h"

namespace psx::gpu {

FrameOutput::FrameOutput() : rgb_(kMaxWidth * kMaxHeight * 3, 0) {}

static inline void put15(u8* out, u16 p) {
  out[0] = expand5(p & 0x1F);
  out[1] = expand5((p >> 5) & 0x1F);
  out[2] = expand5((p >> 10) & 0x1F);
}

// Every 15-bit colour's RGB888 in the low three bytes of a word (expand5() on each channel, in
// memory order on the little-endian x86-64 host), 128 KiB made at compile time: a frame's
// conversion is then a load per pixel instead of a dozen bit operations.
static constexpr std::array<u32, 0x8000> make_rgb_words() {
  std::array<u32, 0x8000> words{};
  for (u32 p = 0; p < 0x8000; ++p)
    words[p] = expand5(p & 0x1F) | u32{expand5((p >> 5) & 0x1F)} << 8 | u32{expand5((p >> 10) & 0x1F)} << 16;
  return words;
}
static constexpr std::array<u32, 0x8000> kRgbWords = make_rgb_words();

// n (at least 1) 15-bit pixels to RGB888: one four-byte store per pixel, whose fourth byte the
// next pixel overwrites, and the last pixel's three bytes on their own.
static void put15_row(u8* out, const u16* pixels, u32 n) {
  for (u32 i = 0; i + 1 < n; ++i) std::memcpy(out + i * 3, &kRgbWords[pixels[i] & 0x7FFF], 4);
  put15(out + (n - 1) * 3, pixels[n - 1]);
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
      // The row wraps at the VRAM's right edge.
      const u32 x = area.x & (kVramWidth - 1), first = std::min(width_, kVramWidth - x);
      put15_row(o, line + x, first);
      if (first < width_) put15_row(o + first * 3, line, width_ - first);
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

void FrameOutput::refresh(const Renderer& renderer, const DisplayArea& area) {
  scale_ = renderer.scale();
  if (scale_ == 1 || !area.enabled || area.rgb24) {
    refresh(renderer.vram(), area);
    if (scale_ > 1) enlarge();
    return;
  }
  width_ = std::clamp<u32>(area.width, 1, kMaxWidth);
  height_ = std::clamp<u32>(area.height, 1, kMaxHeight);
  const u32 w = width_ * scale_, h = height_ * scale_;
  scaled_vram_.resize(size_t{w} * h);
  renderer.read_scaled(area.x, area.y, width_, height_, scaled_vram_.data());
  scaled_.resize(size_t{w} * h * 3);
  put15_row(scaled_.data(), scaled_vram_.data(), w * h);
  // The native picture is each block's top-left sub-pixel, as the renderer's vram() has it.
  for (u32 row = 0; row < height_; ++row)
    for (u32 col = 0; col < width_; ++col)
      put15(&rgb_[(size_t{row} * width_ + col) * 3], scaled_vram_[size_t{row} * scale_ * w + size_t{col} * scale_]);
}

// The scaled picture as the native one with each pixel repeated scale_ x scale_ times.
void FrameOutput::enlarge() {
  const u32 w = width_ * scale_;
  scaled_.resize(size_t{w} * height_ * scale_ * 3);
  for (u32 row = 0; row < height_ * scale_; ++row)
    for (u32 col = 0; col < w; ++col)
      std::memcpy(&scaled_[(size_t{row} * w + col) * 3], &rgb_[(size_t{row / scale_} * width_ + col / scale_) * 3], 3);
}

void FrameOutput::vram_to_rgb(const u16* vram, u8* out) {
  put15_row(out, vram, kVramPixels);
}

void FrameOutput::do_state(StateIO& s) {
  s.section("GPUO", 1);
  s.pod(width_);
  s.pod(height_);
  if (s.loading() && (width_ == 0 || width_ > kMaxWidth || height_ == 0 || height_ > kMaxHeight))
    s.fail("display output size " + std::to_string(width_) + "x" + std::to_string(height_) + " out of range");
  s.bytes(rgb_.data(), size_t{width_} * height_ * 3);
  if (s.loading() && scale_ > 1) enlarge();
  s.end_section("GPUO");
}

}  // namespace psx::gpu
