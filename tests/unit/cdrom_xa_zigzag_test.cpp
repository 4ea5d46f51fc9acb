// XA-ADPCM 37.8 -> 44.1 kHz resampling (psx-spx "25-point Zigzag Interpolation"): a 32-sample
// ring buffer per channel, seven 29-point tables applied after every sixth 37.8 kHz sample,
// products scaled by >> 15 and the sum saturated; 18.9 kHz samples are doubled first. Expected
// values come from the documented table (cdrom_xa_reference.h) and from arithmetic shown here.
#include <gtest/gtest.h>

#include "cdrom_xa_reference.h"
#include "core/cdrom/xa_adpcm.h"

namespace psx {
namespace {

using test::doc_table_sum;
using test::kDocZigZag;
using test::RefXa;

constexpr u32 kSectorBytes = 18 * 128;
using Sector = std::vector<u8>;

// A silent sector: every header shift 0, filter 0, every sample 0.
Sector silent() { return Sector(kSectorBytes, 0); }

// Sets 37.8 kHz mono sample `n` (of 4032) of a 4-bit sector with shift 0 and filter 0 to
// `nibble`, i.e. the sample value (s16)(nibble << 12): 1 -> 4096, 7 -> 28672, 8 -> -32768.
void set_mono4(Sector& s, u32 n, u8 nibble) {
  const u32 group = n / 224, unit = n % 224 / 28, j = n % 28;
  u8& byte = s[group * 128 + 16 + j * 4 + unit / 2];
  byte = (unit & 1) ? static_cast<u8>((byte & 0x0F) | nibble << 4) : static_cast<u8>((byte & 0xF0) | nibble);
}

std::vector<StereoSample> decode(XaAdpcm& xa, const Sector& s, u8 coding) {
  std::vector<StereoSample> out;
  xa.decode_sector(s.data(), coding, out);
  return out;
}

// Deterministic noise sectors with every shift (0..15, reserved ones too) and filter.
Sector noise(u32 seed) {
  Sector s(kSectorBytes);
  for (u8& b : s) {
    seed = seed * 1664525u + 1013904223u;
    b = static_cast<u8>(seed >> 24);
  }
  return s;
}

TEST(XaZigZag, SixInputsGiveSevenOutputs) {
  // 18 groups of 224 nibbles (4-bit) or 112 bytes (8-bit); stereo halves the samples per side,
  // 18.9 kHz doubles them; then 7 frames per 6 samples.
  struct Case { u8 coding; size_t frames; };
  const Case cases[] = {
      {0x00, 4032 * 7 / 6},      {0x01, 2016 * 7 / 6},      {0x04, 4032 * 2 * 7 / 6},
      {0x05, 2016 * 2 * 7 / 6},  {0x10, 2016 * 7 / 6},      {0x11, 1008 * 7 / 6},
  };
  for (const Case& c : cases) {
    XaAdpcm xa;
    EXPECT_EQ(decode(xa, noise(c.coding), c.coding).size(), c.frames) << "coding " << int(c.coding);
  }
  // The reference emits nothing for five inputs and seven frames on the sixth.
  RefXa ref;
  std::vector<StereoSample> six;
  for (int n = 0; n < 5; ++n) ref.zigzag.output_37800hz(1, 1, six);
  EXPECT_EQ(six.size(), 0u);
  ref.zigzag.output_37800hz(1, 1, six);
  EXPECT_EQ(six.size(), 7u);
}

TEST(XaZigZag, ImpulseResponseIsTheDocumentedTable) {
  // One sample of -32768 at input k, zeros elsewhere: (-32768 * t) >> 15 = -t exactly, so the
  // seven frames after input 6(g+1) hold -TableX[i] with i = 6(g+1) - k, the impulse's distance
  // from p. Inputs k = 0..5 together reach every index 1..29.
  for (u32 k = 0; k < 6; ++k) {
    Sector s = silent();
    set_mono4(s, k, 8);
    XaAdpcm xa;
    std::vector<StereoSample> out = decode(xa, s, 0x00);
    for (u32 g = 0; g < 10; ++g) {
      const u32 i = 6 * (g + 1) - k;
      for (u32 t = 0; t < 7; ++t) {
        const s32 want = (i >= 1 && i <= 29) ? -kDocZigZag[i - 1][t] : 0;
        ASSERT_EQ(out[7 * g + t].left, want) << "k " << k << " i " << i << " Table" << t + 1;
        ASSERT_EQ(out[7 * g + t].right, want);
      }
    }
  }
  // Spelled out for k = 0, g = 0 (index 6 of psx-spx's table: -2, +3, -5, +5, +0Ah, +1Ah, -44h).
  Sector s = silent();
  set_mono4(s, 0, 8);
  XaAdpcm xa;
  std::vector<StereoSample> out = decode(xa, s, 0x00);
  const s16 row6[7] = {2, -3, 5, -5, -0x0A, -0x1A, 0x44};
  for (u32 t = 0; t < 7; ++t) EXPECT_EQ(out[t].left, row6[t]);
}

TEST(XaZigZag, ConstantInputConvergesToTheTableSums) {
  // Constant -32768: once the 29 taps are filled (from the fifth six-step on, frames 28+), frame
  // 7g+t is exactly -(sum of Table t+1). The column sums of psx-spx's table are 73EBh, 741Dh,
  // 73E5h, 741Dh, 73EDh, 7408h, 7408h: the decoder's gain is about 0.906.
  const s32 sums[7] = {0x73EB, 0x741D, 0x73E5, 0x741D, 0x73ED, 0x7408, 0x7408};
  for (int t = 0; t < 7; ++t) EXPECT_EQ(doc_table_sum(t), sums[t]) << "Table" << t + 1;
  Sector low = silent();
  for (u32 n = 0; n < 4032; ++n) set_mono4(low, n, 8);
  XaAdpcm xa;
  std::vector<StereoSample> out = decode(xa, low, 0x00);
  for (size_t f = 28; f < out.size(); ++f) ASSERT_EQ(out[f].left, -sums[f % 7]) << "frame " << f;

  // Constant +4096: each of the 29 products is floored on its own, so the result is within 29 of
  // (4096 * sum) >> 15 = sum / 8, and never above it.
  Sector high = silent();
  for (u32 n = 0; n < 4032; ++n) set_mono4(high, n, 1);
  XaAdpcm xb;
  out = decode(xb, high, 0x00);
  for (size_t f = 28; f < out.size(); ++f) {
    const s32 ideal = (4096 * sums[f % 7]) >> 15;
    ASSERT_LE(out[f].left, ideal);
    ASSERT_GE(out[f].left, ideal - 29);
  }
}

TEST(XaZigZag, SumSaturatesTo16Bits) {
  // Inputs chosen with the signs of Table3 (+28672 where TableX[i] > 0, -32768 where < 0): the
  // sum of |products| is 36665 > 32767, so frame 7*4+2 (Table3 after input 30, p = 30, input n
  // at index i = 30 - n) saturates.
  Sector s = silent();
  for (u32 i = 1; i <= 29; ++i) {
    const s32 c = kDocZigZag[i - 1][2];
    if (c != 0) set_mono4(s, 30 - i, c > 0 ? 7 : 8);
  }
  XaAdpcm xa;
  std::vector<StereoSample> out = decode(xa, s, 0x00);
  EXPECT_EQ(out[30].left, 32767);
  // Without the clamp the mirrored input would give -36665: it saturates at -32768.
  Sector m = silent();
  for (u32 i = 1; i <= 29; ++i) {
    const s32 c = kDocZigZag[i - 1][2];
    if (c != 0) set_mono4(m, 30 - i, c > 0 ? 8 : 7);
  }
  XaAdpcm xb;
  EXPECT_EQ(decode(xb, m, 0x00)[30].left, -32768);
}

TEST(XaZigZag, StereoChannelsAreIndependent) {
  // Stereo 4-bit: low nibbles are the left channel, high nibbles the right. Left constant
  // +4096, right silent: the right output stays 0 and the left equals a mono run of +4096.
  Sector st = silent();
  for (u32 b = 0; b < kSectorBytes; b += 128)
    for (u32 d = 16; d < 128; ++d) st[b + d] = 0x01;
  Sector mono = silent();
  for (u32 n = 0; n < 4032; ++n) set_mono4(mono, n, 1);
  XaAdpcm xs, xm;
  std::vector<StereoSample> s_out = decode(xs, st, 0x01);
  std::vector<StereoSample> m_out = decode(xm, mono, 0x00);
  ASSERT_EQ(s_out.size(), 2352u);
  for (size_t f = 0; f < s_out.size(); ++f) {
    ASSERT_EQ(s_out[f].right, 0) << "frame " << f;
    ASSERT_EQ(s_out[f].left, m_out[f].left) << "frame " << f;
  }
  // And the mirror image: right constant -4096 (nibble F), left silent.
  for (u32 b = 0; b < kSectorBytes; b += 128)
    for (u32 d = 16; d < 128; ++d) st[b + d] = 0xF0;
  XaAdpcm xr;
  s_out = decode(xr, st, 0x01);
  for (size_t f = 0; f < s_out.size(); ++f) ASSERT_EQ(s_out[f].left, 0) << "frame " << f;
  EXPECT_LT(s_out.back().right, -3700);
}

TEST(XaZigZag, HalfRateDoublesEachSampleBeforeTheZigZag) {
  // 18.9 kHz: every decoded sample enters the ring buffer twice. A half-rate sector whose first
  // sample is -32768 therefore equals a full-rate stream with -32768 at inputs 0 and 1.
  Sector half = silent(), full = silent();
  set_mono4(half, 0, 8);
  set_mono4(full, 0, 8);
  set_mono4(full, 1, 8);
  XaAdpcm xh, xf;
  std::vector<StereoSample> h = decode(xh, half, 0x04);
  std::vector<StereoSample> f = decode(xf, full, 0x00);
  ASSERT_EQ(h.size(), 2 * f.size());
  for (size_t n = 0; n < f.size(); ++n) ASSERT_EQ(h[n].left, f[n].left) << "frame " << n;
  // Frames 0..6 see the pair at indices 6 and 5: -(TableX[6] + TableX[5]).
  for (u32 t = 0; t < 7; ++t) EXPECT_EQ(h[t].left, -(kDocZigZag[5][t] + kDocZigZag[4][t]));
}

TEST(XaZigZag, MatchesTheDocumentedAlgorithmOnNoise) {
  // Three consecutive noise sectors per format (history and ring buffer carry across sectors),
  // against the plain psx-spx reference.
  for (u8 coding : {0x00, 0x01, 0x04, 0x05, 0x10, 0x11}) {
    XaAdpcm xa;
    RefXa ref;
    for (u32 n = 0; n < 3; ++n) {
      Sector s = noise(coding * 3 + n);
      std::vector<StereoSample> got = decode(xa, s, coding), want;
      ref.decode_sector(s.data(), coding, want);
      ASSERT_EQ(got.size(), want.size());
      for (size_t f = 0; f < got.size(); ++f) {
        ASSERT_EQ(got[f].left, want[f].left) << "coding " << int(coding) << " sector " << n << " frame " << f;
        ASSERT_EQ(got[f].right, want[f].right) << "coding " << int(coding) << " sector " << n << " frame " << f;
      }
    }
  }
}

TEST(XaZigZag, SaveStateCarriesTheRingBuffer) {
  // The frames at the start of a sector still read the previous sector's last 29 samples.
  XaAdpcm a;
  decode(a, noise(7), 0x01);
  StateIO w;
  a.do_state(w);
  XaAdpcm b;
  StateIO r(w.buffer().data(), w.buffer().size());
  b.do_state(r);
  EXPECT_TRUE(r.at_end());
  const Sector next = noise(8);
  std::vector<StereoSample> from_a = decode(a, next, 0x01), from_b = decode(b, next, 0x01);
  XaAdpcm fresh;
  std::vector<StereoSample> from_fresh = decode(fresh, next, 0x01);
  ASSERT_EQ(from_a.size(), from_b.size());
  for (size_t f = 0; f < from_a.size(); ++f) ASSERT_EQ(from_a[f].left, from_b[f].left) << f;
  EXPECT_NE(from_a[0].left, from_fresh[0].left);  // the carried state matters

  // reset() forgets it: the next sector decodes as on a fresh decoder.
  a.reset();
  std::vector<StereoSample> after_reset = decode(a, noise(9), 0x01), fresh2;
  XaAdpcm c;
  fresh2 = decode(c, noise(9), 0x01);
  for (size_t f = 0; f < fresh2.size(); ++f) ASSERT_EQ(after_reset[f].left, fresh2[f].left) << f;
}

TEST(XaZigZag, CorruptStateIsRejected) {
  XaAdpcm a;
  StateIO w;
  a.do_state(w);
  std::vector<u8> blob = w.buffer();
  // Layout after the 12-byte section header (tag, version, length): hist (16 bytes), ring buffers
  // (128), p (4), sixstep.
  blob[12 + 16 + 128 + 4] = 7;  // six-step counter 7 (valid: 1..6)
  XaAdpcm b;
  StateIO r(blob.data(), blob.size());
  EXPECT_THROW(b.do_state(r), StateError);
}

}  // namespace
}  // namespace psx
