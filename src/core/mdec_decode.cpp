// MDEC decompression: run-length decoding, IDCT and colour conversion. The steps follow psx-spx;
// the rounding is the one that reproduces ps1-tests' hardware captures (see mdec_decode.h).
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
// Clip to signed 9 bits, then saturate to signed 8 bits (psx-spx "signed9bit" then "minmax").
s8 clip9(s32 v) { return static_cast<s8>(std::clamp(signed9(v), -128, 127)); }

// A dequantised coefficient in 1/2 units: value x factor (AC: divided by 4, rounding down, so
// one fraction bit of the x/8 product remains), then an even result is moved one unit toward
// zero, so every non-zero coefficient is odd (the DC too). q_scale 0 stores the raw value
// times 2. Saturated to psx-spx's signed 11-bit range (no capture reaches it). Only this
// reading lets the IDCT reproduce the captures: Mednafen's four fraction bits and psx-spx's
// (x + 4) / 8 leave it a level off in 15% or more of the samples.
s32 dequantise(s32 value, s32 factor, bool ac, bool raw) {
  s32 v = raw ? value * 4 : ac ? (value * factor * 2) >> 3 : value * factor * 2;
  if (!raw && v != 0 && (v & 1) == 0) v += v < 0 ? 1 : -1;
  return std::clamp(v, -0x7FF, 0x7FF);
}

// One colour component: clip9(Y + chroma) for 24-bit output (chroma in 1/256 units, rounded).
// For 15-bit output the hardware rounds Y + chroma to 5 bits from the unrounded chroma, so an
// 8-bit level halfway between two 5-bit ones goes up or down with the chroma's fraction (every
// pixel of mdec/frame's 15-bit capture agrees; rounding the 8-bit level misses 4,000 a channel).
u8 component(s32 y, s32 chroma256, bool five_bit) {
  s32 level = clip9(y + ((chroma256 + 0x80) >> 8));
  if (!five_bit) return static_cast<u8>(level ^ 0x80);
  if (level == -128 || level == 127) return level < 0 ? 0 : 31;
  return static_cast<u8>(std::min(31, ((y + 128 + 4) * 256 + chroma256) >> 11));
}
}  // namespace

bool rl_decode_block(const u16* src, size_t size, size_t& pos, const QuantTable& qt, Block& blk) {
  size_t p = pos;
  while (p < size && src[p] == kEndOfBlock) ++p;  // padding before a block is ignored
  if (p >= size) return false;
  blk.fill(0);
  u16 n = src[p++];
  const s32 q_scale = (n >> 10) & 0x3F;
  // q_scale 0 stores raw values times 2 in raster order (psx-spx); otherwise the DC is scaled by
  // the table alone, without q_scale.
  auto at = [&](u32 k) -> s32& { return blk[q_scale ? kZagzig[k] : k]; };
  at(0) = dequantise(signed10(n), qt[0], false, q_scale == 0);
  for (u32 k = 0;;) {
    // A value written at index 63 completes the block without an end code: the hardware reads
    // no further halfword (ps1-tests mdec/frame's data ends every block that way, and only this
    // reading gives its 300 macroblocks and the captured picture).
    if (k == 63) break;
    if (p >= size) return false;
    n = src[p++];
    k += ((n >> 10) & 0x3F) + 1;  // skip zero AC values; FE00h makes k > 63
    if (k > 63) break;
    at(k) = dequantise(signed10(n), qt[k] * q_scale, true, q_scale == 0);
  }
  pos = p;
  return true;
}

void idct(const ScaleTable& scale, const Block& blk, Samples& out) {
  // Columns first (tmp[y][u]), then rows. The first pass multiplies by the table's upper 13 bits,
  // keeps 7 fraction bits of each product (1 + 13 - 7) and 3 of their sum; the second multiplies
  // by the upper 12 bits, keeps 8 fraction bits of each product (3 + 12 - 7) and rounds their
  // sum. This reproduces all 115,200 IDCT outputs that mdec/frame's 24-bit capture determines and
  // every byte of the 8-bit heart block; moving any one truncation point by a bit loses some.
  // |blk| < 2^11, table entries < 2^15: |tmp| < 2^15 and every sum stays inside 32 bits.
  std::array<s32, 64> m13, m12, tmp;
  for (u32 i = 0; i < 64; ++i) {
    m13[i] = scale[i] >> 3;
    m12[i] = scale[i] >> 4;
  }
  for (u32 u = 0; u < 8; ++u)
    for (u32 y = 0; y < 8; ++y) {
      s32 sum = 0;
      for (u32 v = 0; v < 8; ++v) sum += (blk[v * 8 + u] * m13[v * 8 + y]) >> 7;
      tmp[y * 8 + u] = sum >> 4;
    }
  for (u32 y = 0; y < 8; ++y)
    for (u32 x = 0; x < 8; ++x) {
      s32 sum = 0;
      for (u32 u = 0; u < 8; ++u) sum += (tmp[y * 8 + u] * m12[u * 8 + x]) >> 7;
      out[y * 8 + x] = clip9((sum + 0x80) >> 8);
    }
}

void yuv_to_rgb(const Samples& cr, const Samples& cb, const Samples& y, u32 xx, u32 yy, bool five_bit,
                Rgb16x16& out) {
  // R = Y + 1.402 Cr, G = Y - 0.344 Cb - 0.714 Cr, B = Y + 1.772 Cb in 1/256 units; green drops
  // the low bits of each product before the sum (Mednafen's factors and masks: with them every
  // 2x2 pixel group of mdec/frame's 24-bit capture has exactly one Cr, Cb that reproduces it).
  for (u32 row = 0; row < 8; ++row) {
    for (u32 col = 0; col < 8; ++col) {
      u32 c = (col + xx) / 2 + ((row + yy) / 2) * 8;
      s32 lum = y[col + row * 8];
      u8* px = &out[((col + xx) + (row + yy) * 16) * 3];
      px[0] = component(lum, 359 * cr[c], five_bit);
      px[1] = component(lum, ((-88 * cb[c]) & ~0x1F) + ((-183 * cr[c]) & ~0x07), five_bit);
      px[2] = component(lum, 454 * cb[c], five_bit);
    }
  }
}

u8 mono8(s8 y, bool is_signed) { return static_cast<u8>(is_signed ? y : y ^ 0x80); }

u8 mono4(s8 y, bool is_signed) {
  // Rounded to 4 bits, saturating at the top (ps1-tests mdec/4bit: every nibble of its
  // hardware log agrees with this and not with plain truncation).
  u8 n = static_cast<u8>((std::min(127, y + 8) >> 4) & 0xF);
  return is_signed ? n : n ^ 8;
}

u16 rgb15(const u8* rgb, bool is_signed) {
  u16 out = 0;
  for (u32 i = 0; i < 3; ++i) out |= static_cast<u16>((is_signed ? rgb[i] ^ 0x10 : rgb[i]) << (5 * i));
  return out;
}

}  // namespace psx::mdec
