// MDEC tests. Expected pixels come from the textbook floating-point IDCT and YUV->RGB equations
// (within a rounding tolerance), from arithmetic on flat blocks, and from relations psx-spx
// states between the output formats. The hardware's exact rounding is tested against console
// captures in mdec_hw_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <vector>

#include "core/mdec.h"

namespace psx {
namespace {

// psx-spx "zigzag[0..63]".
const int kZig[64] = {0,  1,  5,  6,  14, 15, 27, 28, 2,  4,  7,  13, 16, 26, 29, 42, 3,  8,  12, 17, 25, 30,
                      41, 43, 9,  11, 18, 24, 31, 40, 44, 53, 10, 19, 23, 32, 39, 45, 52, 54, 20, 22, 33, 38,
                      46, 51, 55, 60, 21, 34, 37, 47, 50, 56, 59, 61, 35, 36, 48, 49, 57, 58, 62, 63};
// psx-spx standard scale table (set_scale_table).
const u16 kScale[64] = {
    0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x7D8A, 0x6A6D, 0x471C, 0x18F8, 0xE707,
    0xB8E3, 0x9592, 0x8275, 0x7641, 0x30FB, 0xCF04, 0x89BE, 0x89BE, 0xCF04, 0x30FB, 0x7641, 0x6A6D, 0xE707,
    0x8275, 0xB8E3, 0x471C, 0x7D8A, 0x18F8, 0x9592, 0x5A82, 0xA57D, 0xA57D, 0x5A82, 0x5A82, 0xA57D, 0xA57D,
    0x5A82, 0x471C, 0x8275, 0x18F8, 0x6A6D, 0x9592, 0xE707, 0x7D8A, 0xB8E3, 0x30FB, 0x89BE, 0x7641, 0xCF04,
    0xCF04, 0x7641, 0x89BE, 0x30FB, 0x18F8, 0xB8E3, 0x6A6D, 0x8275, 0x7D8A, 0x9592, 0x471C, 0xE707};

int sx10(int n) { return (n & 0x200) ? (n & 0x3FF) - 0x400 : (n & 0x3FF); }

// Textbook 8x8 IDCT of the de-zigzagged coefficients (for the independent check).
std::vector<double> float_idct(const std::vector<u16>& src, size_t i, const u8* qt) {
  std::vector<double> F(64, 0.0);
  int n = src[i++];
  int q = (n >> 10) & 63, k = 0;
  F[0] = sx10(n) * qt[0];
  for (;;) {
    n = src[i++];
    k += ((n >> 10) & 63) + 1;
    if (k > 63) break;
    int pos = 0;
    while (kZig[pos] != k) ++pos;
    F[pos] = (sx10(n) * qt[k] * q + 4) / 8;
  }
  std::vector<double> f(64);
  const double pi = std::acos(-1.0);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      double sum = 0;
      for (int v = 0; v < 8; ++v)
        for (int u = 0; u < 8; ++u) {
          double cu = u ? 1.0 : 1.0 / std::sqrt(2.0), cv = v ? 1.0 : 1.0 / std::sqrt(2.0);
          sum += cu * cv * F[u + v * 8] * std::cos((2 * x + 1) * u * pi / 16) * std::cos((2 * y + 1) * v * pi / 16);
        }
      f[x + y * 8] = sum / 4;
    }
  return f;
}

std::vector<u32> pack_halfwords(std::vector<u16> h) {
  if (h.size() & 1) h.push_back(0xFE00);  // padding
  std::vector<u32> w;
  for (size_t i = 0; i < h.size(); i += 2) w.push_back(h[i] | static_cast<u32>(h[i + 1]) << 16);
  return w;
}

class MdecTest : public ::testing::Test {
 protected:
  Mdec mdec;
  u8 qt_y[64], qt_uv[64];

  void SetUp() override {
    for (int k = 0; k < 64; ++k) {
      qt_y[k] = static_cast<u8>(1 + k % 7);
      qt_uv[k] = static_cast<u8>(2 + k % 3);
    }
    mdec.io_write(4, 0xE0000000, 4);  // reset, enable both DMA requests
    std::vector<u32> p;
    p.push_back(0x40000001);  // MDEC(2) with the colour table
    for (int i = 0; i < 128; i += 4) {
      const u8* b = i < 64 ? qt_y + i : qt_uv + i - 64;
      p.push_back(b[0] | b[1] << 8 | b[2] << 16 | static_cast<u32>(b[3]) << 24);
    }
    p.push_back(0x60000000);  // MDEC(3)
    for (int i = 0; i < 64; i += 2) p.push_back(kScale[i] | static_cast<u32>(kScale[i + 1]) << 16);
    mdec.dma_in().dma_write(p.data(), static_cast<u32>(p.size()));
  }
  std::vector<u32> decode(u32 command, const std::vector<u16>& data, u32 out_words) {
    std::vector<u32> params = pack_halfwords(data);
    u32 cmd = command | static_cast<u32>(params.size());
    mdec.dma_in().dma_write(&cmd, 1);
    mdec.dma_in().dma_write(params.data(), static_cast<u32>(params.size()));
    std::vector<u32> out(out_words);
    mdec.dma_out().dma_read(out.data(), out_words);
    return out;
  }
};

// A luminance block: DC 40 with q_scale 8, AC -13 (run 0), 7 (run 2), 100 (run 5), EOB.
const std::vector<u16> kBlockY = {(8 << 10) | 40, (0 << 10) | (-13 & 0x3FF), (2 << 10) | 7, (5 << 10) | 100, 0xFE00};

TEST_F(MdecTest, StatusAfterResetAndTables) {
  Mdec fresh;
  fresh.io_write(4, 0x80000000, 4);
  EXPECT_EQ(fresh.io_read(4, 4), 0x80040000u);  // psx-spx: reset sets status 80040000h
  u32 cmd = 0x40000000;  // quant table, luminance only: 16 words
  fresh.io_write(4, 0x40000000, 4);
  fresh.io_write(0, cmd, 4);
  u32 s = fresh.io_read(4, 4);
  EXPECT_EQ(s & 0xFFFF, 15u);  // parameter words remaining minus 1
  EXPECT_NE(s & (1u << 29), 0u);  // busy
  EXPECT_NE(s & (1u << 28), 0u);  // data-in request (enabled)
  for (int i = 0; i < 16; ++i) fresh.io_write(0, 0, 4);
  EXPECT_EQ(fresh.io_read(4, 4), 0x8004FFFFu);  // done: remaining 0, minus 1 = FFFFh
}

TEST_F(MdecTest, NoFunctionCommandReflectsBits) {
  mdec.io_write(0, 0x1E001234, 4);  // MDEC(0), bits 25-28 = 1111
  EXPECT_EQ(mdec.io_read(4, 4), 0x80000000u | (0xFu << 23) | (4u << 16) | 0x1234);
}

TEST_F(MdecTest, MonoBlockAgreesWithTheTextbookIdct) {
  // MDEC(1), 8-bit mono (depth 1), unsigned.
  std::vector<u32> out = decode(0x28000000, kBlockY, 16);
  std::vector<double> f = float_idct(kBlockY, 0, qt_y);
  for (int p = 0; p < 64; ++p) {
    u32 got = (out[p / 4] >> (8 * (p % 4))) & 0xFF;
    int want = static_cast<int>(std::lround(f[p]));
    want = (want < -128 ? -128 : want > 127 ? 127 : want) + 128;
    EXPECT_NEAR(static_cast<int>(got), want, 2) << "pixel " << p;
  }
  EXPECT_EQ(mdec.io_read(4, 4) & 0xE000'0000u, 0x8000'0000u);  // output empty, not busy
}

TEST_F(MdecTest, Mono4BitAndSigned) {
  // psx-spx: signed output is the unsigned one with the top bit flipped; 4-bit output is the
  // 8-bit sample to 4 bits (first pixel in the low nibble).
  std::vector<u32> out8u = decode(0x28000000, kBlockY, 16);  // 8-bit unsigned
  std::vector<u32> out8 = decode(0x2C000000, kBlockY, 16);   // 8-bit signed
  std::vector<u32> out4 = decode(0x24000000, kBlockY, 8);    // 4-bit signed
  std::vector<u32> out4u = decode(0x20000000, kBlockY, 8);   // 4-bit unsigned
  for (int p = 0; p < 64; ++p) {
    u32 byte = (out8[p / 4] >> (8 * (p % 4))) & 0xFF;
    EXPECT_EQ(byte ^ 0x80, (out8u[p / 4] >> (8 * (p % 4))) & 0xFF) << "pixel " << p;
    u32 s4 = (out4[p / 8] >> (4 * (p % 8))) & 0xF;
    EXPECT_EQ(s4 ^ 8, (out4u[p / 8] >> (4 * (p % 8))) & 0xF) << "pixel " << p;
    int y = static_cast<s8>(byte), n = static_cast<int>(s4 ^ 8) - 8;  // both signed
    EXPECT_LT(std::abs(n * 16 - y), 16) << "pixel " << p;  // within one 4-bit step
  }
}

TEST_F(MdecTest, ColourMacroblock24BitMatchesFloatReference) {
  std::vector<u16> cr = {(4 << 10) | 20, (1 << 10) | 5, 0xFE00};
  std::vector<u16> cb = {(4 << 10) | (-15 & 0x3FF), 0xFE00};
  std::vector<u16> data = cr;
  data.insert(data.end(), cb.begin(), cb.end());
  std::vector<u16> ys[4] = {kBlockY, {(8 << 10) | 10, 0xFE00}, {(8 << 10) | (-20 & 0x3FF), (3 << 10) | 9, 0xFE00}, kBlockY};
  for (auto& y : ys) data.insert(data.end(), y.begin(), y.end());
  std::vector<u32> out = decode(0x30000000, data, 192);  // 24-bit unsigned
  std::vector<double> fcr = float_idct(cr, 0, qt_uv), fcb = float_idct(cb, 0, qt_uv);
  for (int py = 0; py < 16; ++py)
    for (int px = 0; px < 16; ++px) {
      int b = (px >= 8) + 2 * (py >= 8);
      std::vector<double> fy = float_idct(ys[b], 0, qt_y);
      double y = fy[(px % 8) + (py % 8) * 8];
      double r = fcr[px / 2 + (py / 2) * 8], c = fcb[px / 2 + (py / 2) * 8];
      double rgb[3] = {y + 1.402 * r, y - 0.3437 * c - 0.7143 * r, y + 1.772 * c};
      for (int k = 0; k < 3; ++k) {
        u32 byte_index = (px + py * 16) * 3 + k;
        int got = (out[byte_index / 4] >> (8 * (byte_index % 4))) & 0xFF;
        int want = static_cast<int>(std::lround(rgb[k]));
        want = (want < -128 ? -128 : want > 127 ? 127 : want) + 128;
        EXPECT_NEAR(got, want, 3) << "x " << px << " y " << py << " component " << k;
      }
    }
}

TEST_F(MdecTest, Colour15BitGreyExactAndRegisterOrder) {
  // Cr = Cb = 0 makes R = G = B = Y exactly; each Y block is flat (DC only) with its own level:
  // a DC of dc * qt_y[0] = dc is dc / 8 in every pixel (multiples of 8 here, so no rounding), and
  // the 15-bit component is (Y + 128) rounded to 5 bits.
  std::vector<u16> data = {0x0000 | (1 << 10), 0xFE00, 0x0000 | (1 << 10), 0xFE00};
  const int dc[4] = {40, -32, 96, 8};
  for (int b = 0; b < 4; ++b) {
    data.push_back(static_cast<u16>((8 << 10) | (dc[b] & 0x3FF)));
    data.push_back(0xFE00);
  }
  u32 cmd = 0x3A000000;  // 15-bit, unsigned, bit 15 set
  std::vector<u32> dma = decode(cmd, data, 128);
  u32 level[4];
  for (int b = 0; b < 4; ++b) level[b] = static_cast<u32>(dc[b] / 8 + 128 + 4) >> 3;
  for (int p = 0; p < 256; ++p) {
    int b = ((p % 16) >= 8) + 2 * ((p / 16) >= 8);
    u32 want = level[b] | level[b] << 5 | level[b] << 10 | 0x8000;
    EXPECT_EQ((dma[p / 2] >> (16 * (p % 2))) & 0xFFFF, want) << "pixel " << p;
  }
  // Through the data register the same macroblock comes out as four 8x8 blocks (Y1..Y4).
  std::vector<u32> params = pack_halfwords(data);
  mdec.io_write(0, cmd | static_cast<u32>(params.size()), 4);
  for (u32 w : params) mdec.io_write(0, w, 4);
  for (int b = 0; b < 4; ++b) {
    EXPECT_EQ((mdec.io_read(4, 4) >> 16) & 7, static_cast<u32>(b));  // current output block
    for (int k = 0; k < 32; ++k) {
      u32 want = level[b] | level[b] << 5 | level[b] << 10 | 0x8000;
      EXPECT_EQ(mdec.io_read(0, 4), want | want << 16) << "block " << b << " word " << k;
    }
  }
  EXPECT_NE(mdec.io_read(4, 4) & (1u << 31), 0u);
}

TEST_F(MdecTest, DmaRequestBitsFollowData) {
  EXPECT_FALSE(mdec.dma_in().dma_request());
  EXPECT_FALSE(mdec.dma_out().dma_request());
  std::vector<u32> p = pack_halfwords(kBlockY);
  u32 cmd = 0x28000000 | static_cast<u32>(p.size());
  mdec.dma_in().dma_write(&cmd, 1);
  EXPECT_TRUE(mdec.dma_in().dma_request());
  EXPECT_NE(mdec.io_read(4, 4) & (1u << 28), 0u);
  mdec.dma_in().dma_write(p.data(), static_cast<u32>(p.size()));
  EXPECT_FALSE(mdec.dma_in().dma_request());
  EXPECT_TRUE(mdec.dma_out().dma_request());
  EXPECT_NE(mdec.io_read(4, 4) & (1u << 27), 0u);
  mdec.io_write(4, 0x40000000, 4);  // data-in enabled, data-out request disabled
  EXPECT_FALSE(mdec.dma_out().dma_request());
}

TEST_F(MdecTest, NoScaleTableGivesFlatGrey) {
  Mdec fresh;  // never sent MDEC(3): the scale matrix is zero
  std::vector<u32> p = pack_halfwords(kBlockY);
  u32 cmd = 0x28000000 | static_cast<u32>(p.size());
  fresh.dma_in().dma_write(&cmd, 1);
  fresh.dma_in().dma_write(p.data(), static_cast<u32>(p.size()));
  std::vector<u32> out(16);
  fresh.dma_out().dma_read(out.data(), 16);
  for (u32 w : out) EXPECT_EQ(w, 0x80808080u);
}

TEST_F(MdecTest, SaveStateMidDecode) {
  std::vector<u32> p = pack_halfwords(kBlockY);
  u32 cmd = 0x28000000 | static_cast<u32>(p.size() + 2);  // two more words still to come
  mdec.dma_in().dma_write(&cmd, 1);
  mdec.dma_in().dma_write(p.data(), static_cast<u32>(p.size()));
  StateIO out;
  mdec.do_state(out);
  Mdec copy;
  StateIO in(out.buffer().data(), out.buffer().size());
  copy.do_state(in);
  EXPECT_TRUE(in.at_end());
  EXPECT_EQ(copy.status(), mdec.status());
  std::vector<u32> a(16), b(16);
  mdec.dma_out().dma_read(a.data(), 16);
  copy.dma_out().dma_read(b.data(), 16);
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace psx
