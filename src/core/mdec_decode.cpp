// MDEC decompression: run-length decoding, IDCT and colour conversion (psx-spx pseudo code).
#include "core/mdec_decode.h"

#include <algorithm>

namespace psx::mdec {

// constexpr (the header declares it extern const) so make_zagzig() below is a constant expression
// for every compiler; GCC accepted the plain const, clang does not.
constexpr std::array<u8, 64> kZigzag = {
    0,  1,  5,  6,  14, 15, 27, 28, 2,  4,  7,  13, 16, 26, 29, 42, 3,  8,  12, 17, 25, 30,
    41, 43, 9,  11, 18, 24, 31, 40, 44, 53, 10, 19, 23, 32, 39, 45, 52, 54, 20, 22, 33, 38,
    46, 51, 55, 60, 21, 34, 37, 47, 50, 56, 59, 61, 35, 36, 48, 49, 57, 58, 62, 63};

namespace {
constexpr u16 kEndOfBlock = 0xFE00;

// zagzig[scan index] = position (the inverse of kZigzag).
constexpr std::array<u8, 64> make_zagzig() {
  std::array<u8, 64> z{};
  for (u32 i = 0; i < 64; ++i) z[kZigzag[i]] = static_cast<u8>(i);
  return z;
}
constexpr std::array<u8, 64> kZagzig = make_zagzig();

s32 signed10(u16 n) { return static_cast<s32>(static_cast<u32>(n & 0x3FF) << 22) >> 22; }
s32 signed9(s32 v) { return static_cast<s32>(static_cast<u32>(v & 0x1FF) << 23) >> 23; }

// Clip to signed 9 bits, saturate to signed 8 bits, then offset by 128 for unsigned output.
u8 to_output(s32 v, bool is_signed) {
  s32 c = std::clamp(signed9(v), -128, 127);
  return static_cast<u8>(is_signed ? c : c ^ 0x80);
}

// YUV->RGB factors in 1/4096 units: R = 1.402 Cr, G = -0.3437 Cb - 0.7143 Cr, B = 1.772 Cb.
// The hardware's exact fixed-point resolution is undocumented.
constexpr s32 kCrToR = 5743, kCbToG = -1408, kCrToG = -2926, kCbToB = 7258;
s32 scale_round(s32 factor, s32 v) { return (factor * v + 2048) >> 12; }
}  // namespace

bool rl_decode_block(const u16* src, size_t size, size_t& pos, const QuantTable& qt, Block& blk) {
  size_t p = pos;
  while (p < size && src[p] == kEndOfBlock) ++p;  // padding before a block is ignored
  if (p >= size) return false;
  blk.fill(0);
  u16 n = src[p++];
  u32 q_scale = (n >> 10) & 0x3F;
  u32 k = 0;
  s32 val = signed10(n) * qt[0];  // DC: quant table only, no q_scale/8
  for (;;) {
    if (q_scale == 0) val = signed10(n) * 2;  // special mode: no quantisation, no zigzag
    val = std::clamp(val, -0x400, 0x3FF);
    blk[q_scale ? kZagzig[k] : k] = val;
    if (p >= size) return false;
    n = src[p++];
    k += ((n >> 10) & 0x3F) + 1;  // skip zero AC values; FE00h makes k > 63
    if (k > 63) break;
    val = (signed10(n) * qt[k] * static_cast<s32>(q_scale) + 4) / 8;
  }
  pos = p;
  return true;
}

void idct(const ScaleTable& scale, Block& blk) {
  Block tmp{};
  Block* src = &blk;
  Block* dst = &tmp;
  for (int pass = 0; pass < 2; ++pass) {
    for (u32 x = 0; x < 8; ++x) {
      for (u32 y = 0; y < 8; ++y) {
        s32 sum = 0;
        for (u32 z = 0; z < 8; ++z) sum += (*src)[y + z * 8] * (scale[x + z * 8] >> 3);
        (*dst)[x + y * 8] = (sum + 0xFFF) >> 13;  // strip the fraction, rounding up above one half
      }
    }
    std::swap(src, dst);
  }
  // After two passes the result is back in blk.
}

void yuv_to_rgb(const Block& cr, const Block& cb, const Block& y, u32 xx, u32 yy, bool is_signed, Rgb16x16& out) {
  for (u32 row = 0; row < 8; ++row) {
    for (u32 col = 0; col < 8; ++col) {
      u32 c = (col + xx) / 2 + ((row + yy) / 2) * 8;
      s32 r = scale_round(kCrToR, cr[c]);
      s32 g = scale_round(kCbToG, cb[c]) + scale_round(kCrToG, cr[c]);
      s32 b = scale_round(kCbToB, cb[c]);
      s32 lum = y[col + row * 8];
      u8* px = &out[((col + xx) + (row + yy) * 16) * 3];
      px[0] = to_output(lum + r, is_signed);
      px[1] = to_output(lum + g, is_signed);
      px[2] = to_output(lum + b, is_signed);
    }
  }
}

void y_to_mono(const Block& y, bool is_signed, Mono8x8& out) {
  for (u32 i = 0; i < 64; ++i) out[i] = to_output(y[i], is_signed);
}

}  // namespace psx::mdec
