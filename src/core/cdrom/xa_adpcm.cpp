// XA-ADPCM sound-group decoding and the CD decoder's 37.8 -> 44.1 kHz zigzag resampler.
#include "core/cdrom/xa_adpcm.h"

#include <algorithm>

namespace psx {
namespace {

// Prediction filters (psx-spx "XA-ADPCM Decoding"): coefficients in 1/64 units.
constexpr s32 kPos[4] = {0, 60, 115, 98};
constexpr s32 kNeg[4] = {0, 0, -52, -55};
constexpr u32 kGroups = 18;
constexpr u32 kGroupSize = 128;
constexpr u32 kSamplesPerUnit = 28;

// psx-spx "25-point Zigzag Interpolation": Table1..Table7, each listed from TableX[1] (applied to
// the newest ring buffer sample, ringbuf[p-1]) to TableX[29] (the oldest, ringbuf[p-29]).
// Coefficients are in 1/8000h units; each table sums to about 0.9 (the decoder's gain).
constexpr s16 kZigZag[XaAdpcm::kZigZagTables][XaAdpcm::kZigZagTaps] = {
    {0, 0, 0, 0, 0, -0x0002, 0x000A, -0x0022, 0x0041, -0x0054,
     0x0034, 0x0009, -0x010A, 0x0400, -0x0A78, 0x234C, 0x6794, -0x1780, 0x0BCD, -0x0623,
     0x0350, -0x016D, 0x006B, 0x000A, -0x0010, 0x0011, -0x0008, 0x0003, -0x0001},
    {0, 0, 0, -0x0002, 0, 0x0003, -0x0013, 0x003C, -0x004B, 0x00A2,
     -0x00E3, 0x0132, -0x0043, -0x0267, 0x0C9D, 0x74BB, -0x11B4, 0x09B8, -0x05BF, 0x0372,
     -0x01A8, 0x00A6, -0x001B, 0x0005, 0x0006, -0x0008, 0x0003, -0x0001, 0},
    {0, 0, -0x0001, 0x0003, -0x0002, -0x0005, 0x001F, -0x004A, 0x00B3, -0x0192,
     0x02B1, -0x039E, 0x04F8, -0x05A6, 0x7939, -0x05A6, 0x04F8, -0x039E, 0x02B1, -0x0192,
     0x00B3, -0x004A, 0x001F, -0x0005, -0x0002, 0x0003, -0x0001, 0, 0},
    {0, -0x0001, 0x0003, -0x0008, 0x0006, 0x0005, -0x001B, 0x00A6, -0x01A8, 0x0372,
     -0x05BF, 0x09B8, -0x11B4, 0x74BB, 0x0C9D, -0x0267, -0x0043, 0x0132, -0x00E3, 0x00A2,
     -0x004B, 0x003C, -0x0013, 0x0003, 0, -0x0002, 0, 0, 0},
    {-0x0001, 0x0003, -0x0008, 0x0011, -0x0010, 0x000A, 0x006B, -0x016D, 0x0350, -0x0623,
     0x0BCD, -0x1780, 0x6794, 0x234C, -0x0A78, 0x0400, -0x010A, 0x0009, 0x0034, -0x0054,
     0x0041, -0x0022, 0x000A, -0x0001, 0, 0x0001, 0, 0, 0},
    {0x0002, -0x0008, 0x0010, -0x0023, 0x002B, 0x001A, -0x00EB, 0x027B, -0x0548, 0x0AFA,
     -0x16FA, 0x53E0, 0x3C07, -0x1249, 0x080E, -0x0347, 0x015B, -0x0044, -0x0017, 0x0046,
     -0x0023, 0x0011, -0x0005, 0, 0, 0, 0, 0, 0},
    {-0x0005, 0x0011, -0x0023, 0x0046, -0x0017, -0x0044, 0x015B, -0x0347, 0x080E, -0x1249,
     0x3C07, 0x53E0, -0x16FA, 0x0AFA, -0x0548, 0x027B, -0x00EB, 0x001A, 0x002B, -0x0023,
     0x0010, -0x0008, 0x0002, 0, 0, 0, 0, 0, 0},
};

}  // namespace

void XaAdpcm::reset() {
  for (auto& h : hist_) h[0] = h[1] = 0;
  for (auto& ring : ringbuf_) std::fill(std::begin(ring), std::end(ring), 0);
  p_ = 0;
  sixstep_ = kSixStep;
}

s16 XaAdpcm::decode_unit_sample(s32 raw, u32 shift, u32 filter, s32 hist[2]) {
  s32 s = (raw >> shift) + ((hist[1] * kPos[filter] + hist[0] * kNeg[filter] + 32) >> 6);
  s = std::clamp(s, -32768, 32767);
  hist[0] = hist[1];
  hist[1] = s;
  return static_cast<s16>(s);
}

// A group holds 8 units of 4-bit samples or 4 units of 8-bit samples, 28 samples each. In
// stereo, even units are the left channel and odd units the right.
void XaAdpcm::decode_group(const u8* group, bool eight, bool st, s16* left, s16* right, u32& nl, u32& nr) {
  const u32 units = eight ? 4 : 8;
  for (u32 u = 0; u < units; ++u) {
    u8 param = group[4 + u];
    u32 shift = param & 0x0F;
    if (shift > 12) shift = 9;  // reserved values act as 9
    u32 filter = (param >> 4) & 3;
    bool is_right = st && (u & 1);
    s32* hist = hist_[is_right ? 1 : 0];
    for (u32 j = 0; j < kSamplesPerUnit; ++j) {
      u8 byte = group[16 + j * 4 + (eight ? u : u / 2)];
      s32 raw = eight ? static_cast<s16>(byte << 8)
                      : static_cast<s16>(((u & 1) ? byte >> 4 : byte & 0x0F) << 12);
      s16 v = decode_unit_sample(raw, shift, filter, hist);
      if (is_right) right[nr++] = v;
      else left[nl++] = v;
    }
  }
}

// ZigZagInterpolate(p, TableX): sum of ringbuf[(p-i) AND 1Fh] * TableX[i] / 8000h for i = 1..29,
// each product scaled on its own (arithmetic >> 15), then saturated to 16 bits.
s16 XaAdpcm::zigzag_interpolate(const s16* ringbuf, u32 table) const {
  s32 sum = 0;
  for (u32 i = 1; i <= kZigZagTaps; ++i)
    sum += (ringbuf[(p_ - i) & (kRingSize - 1)] * static_cast<s32>(kZigZag[table][i - 1])) >> 15;
  return static_cast<s16>(std::clamp(sum, -32768, 32767));
}

// Output37800Hz: store the sample, and after every sixth one emit seven 44.1 kHz frames. The
// hardware's six-step counter starts at a random value on power-up; ours starts at 6 so the
// output is deterministic. A sector holds a multiple of six samples, so the counter is the same
// at every sector boundary.
void XaAdpcm::output_37800hz(s16 l, s16 r, std::vector<StereoSample>& out) {
  ringbuf_[0][p_] = l;
  ringbuf_[1][p_] = r;
  p_ = (p_ + 1) & (kRingSize - 1);
  if (--sixstep_ != 0) return;
  sixstep_ = kSixStep;
  for (u32 t = 0; t < kZigZagTables; ++t)
    out.push_back({zigzag_interpolate(ringbuf_[0], t), zigzag_interpolate(ringbuf_[1], t)});
}

void XaAdpcm::decode_sector(const u8* data, u8 coding, std::vector<StereoSample>& out) {
  const bool st = stereo(coding), eight = eight_bit(coding), half = half_rate(coding);
  s16 left[kGroups * 8 * kSamplesPerUnit], right[kGroups * 4 * kSamplesPerUnit];
  u32 nl = 0, nr = 0;
  for (u32 g = 0; g < kGroups; ++g) decode_group(data + g * kGroupSize, eight, st, left, right, nl, nr);
  for (u32 i = 0; i < nl; ++i) {
    s16 r = st && i < nr ? right[i] : left[i];
    for (int rep = 0; rep < (half ? 2 : 1); ++rep) output_37800hz(left[i], r, out);
  }
}

void XaAdpcm::do_state(StateIO& s) {
  s.section("XADP", 2);
  s.pod(hist_);
  s.pod(ringbuf_);
  s.pod(p_);
  s.pod(sixstep_);
  if (s.loading() && (p_ >= kRingSize || sixstep_ < 1 || sixstep_ > kSixStep))
    s.fail("XA resampler position or six-step counter out of range");
  s.end_section("XADP");
}

}  // namespace psx
