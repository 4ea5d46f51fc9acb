// Test-side reference for XA-ADPCM audio, written straight from psx-spx "CDROM XA Audio ADPCM
// Compression" (decode_sector, decode_28_nibbles, Output37800Hz, ZigZagInterpolate) without
// using the production decoder: the expected values of the CD audio tests come from here.
#pragma once
#include <algorithm>
#include <vector>

#include "core/audio_fifo.h"
#include "core/types.h"

namespace psx::test {

// The zigzag table exactly as psx-spx prints it: row i-1 holds TableX[i] for Table1..Table7.
constexpr s32 kDocZigZag[29][7] = {
    {      0,       0,       0,       0, -0x0001, +0x0002, -0x0005},  // 1
    {      0,       0,       0, -0x0001, +0x0003, -0x0008, +0x0011},  // 2
    {      0,       0, -0x0001, +0x0003, -0x0008, +0x0010, -0x0023},  // 3
    {      0, -0x0002, +0x0003, -0x0008, +0x0011, -0x0023, +0x0046},  // 4
    {      0,       0, -0x0002, +0x0006, -0x0010, +0x002B, -0x0017},  // 5
    {-0x0002, +0x0003, -0x0005, +0x0005, +0x000A, +0x001A, -0x0044},  // 6
    {+0x000A, -0x0013, +0x001F, -0x001B, +0x006B, -0x00EB, +0x015B},  // 7
    {-0x0022, +0x003C, -0x004A, +0x00A6, -0x016D, +0x027B, -0x0347},  // 8
    {+0x0041, -0x004B, +0x00B3, -0x01A8, +0x0350, -0x0548, +0x080E},  // 9
    {-0x0054, +0x00A2, -0x0192, +0x0372, -0x0623, +0x0AFA, -0x1249},  // 10
    {+0x0034, -0x00E3, +0x02B1, -0x05BF, +0x0BCD, -0x16FA, +0x3C07},  // 11
    {+0x0009, +0x0132, -0x039E, +0x09B8, -0x1780, +0x53E0, +0x53E0},  // 12
    {-0x010A, -0x0043, +0x04F8, -0x11B4, +0x6794, +0x3C07, -0x16FA},  // 13
    {+0x0400, -0x0267, -0x05A6, +0x74BB, +0x234C, -0x1249, +0x0AFA},  // 14
    {-0x0A78, +0x0C9D, +0x7939, +0x0C9D, -0x0A78, +0x080E, -0x0548},  // 15
    {+0x234C, +0x74BB, -0x05A6, -0x0267, +0x0400, -0x0347, +0x027B},  // 16
    {+0x6794, -0x11B4, +0x04F8, -0x0043, -0x010A, +0x015B, -0x00EB},  // 17
    {-0x1780, +0x09B8, -0x039E, +0x0132, +0x0009, -0x0044, +0x001A},  // 18
    {+0x0BCD, -0x05BF, +0x02B1, -0x00E3, +0x0034, -0x0017, +0x002B},  // 19
    {-0x0623, +0x0372, -0x0192, +0x00A2, -0x0054, +0x0046, -0x0023},  // 20
    {+0x0350, -0x01A8, +0x00B3, -0x004B, +0x0041, -0x0023, +0x0010},  // 21
    {-0x016D, +0x00A6, -0x004A, +0x003C, -0x0022, +0x0011, -0x0008},  // 22
    {+0x006B, -0x001B, +0x001F, -0x0013, +0x000A, -0x0005, +0x0002},  // 23
    {+0x000A, +0x0005, -0x0005, +0x0003, -0x0001,       0,       0},  // 24
    {-0x0010, +0x0006, -0x0002,       0,       0,       0,       0},  // 25
    {+0x0011, -0x0008, +0x0003, -0x0002, +0x0001,       0,       0},  // 26
    {-0x0008, +0x0003, -0x0001,       0,       0,       0,       0},  // 27
    {+0x0003, -0x0001,       0,       0,       0,       0,       0},  // 28
    {-0x0001,       0,       0,       0,       0,       0,       0},  // 29
};

inline s32 doc_table_sum(int table) {
  s32 sum = 0;
  for (int i = 0; i < 29; ++i) sum += kDocZigZag[i][table];
  return sum;
}

// Output37800Hz / ZigZagInterpolate. psx-spx writes the scaling as "/8000h"; like its "/64" in
// decode_28_nibbles it is taken as an arithmetic shift (>> 15) of each product. The six-step
// counter starts at 6 (its power-up value is random on hardware).
struct RefZigZag {
  s16 ringbuf[2][32] = {};
  u32 p = 0;
  int sixstep = 6;

  s16 interpolate(int ch, int table) const {
    s32 sum = 0;
    for (u32 i = 1; i <= 29; ++i) sum += (ringbuf[ch][(p - i) & 0x1F] * kDocZigZag[i - 1][table]) >> 15;
    return static_cast<s16>(std::clamp(sum, -0x8000, 0x7FFF));
  }
  void output_37800hz(s16 left, s16 right, std::vector<StereoSample>& out) {
    ringbuf[0][p & 0x1F] = left;
    ringbuf[1][p & 0x1F] = right;
    p = p + 1;
    sixstep = sixstep - 1;
    if (sixstep == 0) {
      sixstep = 6;
      for (int table = 0; table < 7; ++table) out.push_back({interpolate(0, table), interpolate(1, table)});
    }
  }
};

// decode_sector / decode_28_nibbles, plus the same walk for 8-bit samples (4 blocks of one byte
// each per data word, sample = (byte SHL 8) SAR shift). Mono goes to both sides; 18.9 kHz
// samples are output twice at 37.8 kHz.
struct RefXa {
  s32 old[2] = {}, older[2] = {};
  RefZigZag zigzag;

  static s32 header_shift(u8 hdr) {
    s32 range = hdr & 0x0F;
    return range > 12 ? 9 : range;  // reserved 13..15 act as 9
  }
  void decode_28(const u8* src, int blk, int nibble, bool eight, std::vector<s16>& dst, int ch) {
    const u8 hdr = eight ? src[4 + blk] : src[4 + blk * 2 + nibble];
    const s32 range = header_shift(hdr);
    const s32 filter = (hdr & 0x30) >> 4;
    const s32 f0[4] = {0, 60, 115, 98}, f1[4] = {0, 0, -52, -55};
    for (int j = 0; j < 28; ++j) {
      s32 s;
      if (eight) {
        s32 t = static_cast<s8>(src[16 + blk + j * 4]);
        s = ((t * 256) >> range);
      } else {
        s32 t = (src[16 + blk + j * 4] >> (nibble * 4)) & 0x0F;
        if (t >= 8) t -= 16;  // signed4bit
        s = t * (1 << (12 - range));
      }
      s += (old[ch] * f0[filter] + older[ch] * f1[filter] + 32) >> 6;
      s = std::clamp(s, -0x8000, 0x7FFF);
      dst.push_back(static_cast<s16>(s));
      older[ch] = old[ch];
      old[ch] = s;
    }
  }
  void decode_sector(const u8* src, u8 coding, std::vector<StereoSample>& out) {
    const bool stereo = (coding & 3) == 1, half = (coding & 0x0C) == 4, eight = (coding & 0x30) == 0x10;
    std::vector<s16> left, right;
    for (int i = 0; i < 18; ++i, src += 128) {
      if (eight) {
        for (int blk = 0; blk < 4; ++blk)
          decode_28(src, blk, 0, true, stereo && (blk & 1) ? right : left, stereo && (blk & 1) ? 1 : 0);
        continue;
      }
      for (int blk = 0; blk < 4; ++blk) {
        decode_28(src, blk, 0, false, left, 0);
        decode_28(src, blk, 1, false, stereo ? right : left, stereo ? 1 : 0);
      }
    }
    for (size_t n = 0; n < left.size(); ++n) {
      s16 r = stereo ? right[n] : left[n];
      zigzag.output_37800hz(left[n], r, out);
      if (half) zigzag.output_37800hz(left[n], r, out);
    }
  }
};

}  // namespace psx::test
