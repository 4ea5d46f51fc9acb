// GPU video RAM (psx-spx "GPU Video Memory (VRAM)"): 1 MiB seen as 1024x512 halfwords, each a
// 15-bit BGR pixel (bits 0-4 red, 5-9 green, 10-14 blue) with the mask bit in bit 15. Texture
// pages, CLUTs, the display buffer and the drawing buffer all live in it.
#pragma once
#include "core/types.h"

namespace psx::gpu {

constexpr u32 kVramWidth = 1024;
constexpr u32 kVramHeight = 512;
constexpr u32 kVramPixels = kVramWidth * kVramHeight;
constexpr u16 kMaskBit = 0x8000;

constexpr u32 vram_index(u32 x, u32 y) { return (y & (kVramHeight - 1)) * kVramWidth + (x & (kVramWidth - 1)); }

// GP0 colour words carry 8 bits per channel; VRAM keeps the top 5 (GP0(02) fill, rectangles).
constexpr u16 rgb24_to_15(u32 c) {
  return static_cast<u16>(((c >> 3) & 0x1F) | (((c >> 11) & 0x1F) << 5) | (((c >> 19) & 0x1F) << 10));
}

// Display conversion of a 5-bit channel to 8 bits: the video DAC sees c5 << 3 (psx-spx shows
// the low three bits as zero); we replicate the top bits so that white is 255 in screenshots.
constexpr u8 expand5(u32 c5) { return static_cast<u8>((c5 << 3) | (c5 >> 2)); }

}  // namespace psx::gpu
