// XA-ADPCM sound-group decoding and 37.8 -> 44.1 kHz resampling.
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

}  // namespace

void XaAdpcm::reset() {
  for (auto& h : hist_) h[0] = h[1] = 0;
  prev_[0] = prev_[1] = 0;
  phase_ = 0;
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

void XaAdpcm::resample(s16 l, s16 r, std::vector<StereoSample>& out) {
  // Seven output samples per six input samples: emit at positions phase/7 between prev and now.
  while (phase_ < 7) {
    s32 a = prev_[0] + (l - prev_[0]) * static_cast<s32>(phase_) / 7;
    s32 b = prev_[1] + (r - prev_[1]) * static_cast<s32>(phase_) / 7;
    out.push_back({static_cast<s16>(a), static_cast<s16>(b)});
    phase_ += 6;
  }
  phase_ -= 7;
  prev_[0] = l;
  prev_[1] = r;
}

void XaAdpcm::decode_sector(const u8* data, u8 coding, std::vector<StereoSample>& out) {
  const bool st = stereo(coding), eight = eight_bit(coding), half = half_rate(coding);
  s16 left[kGroups * 8 * kSamplesPerUnit], right[kGroups * 4 * kSamplesPerUnit];
  u32 nl = 0, nr = 0;
  for (u32 g = 0; g < kGroups; ++g) decode_group(data + g * kGroupSize, eight, st, left, right, nl, nr);
  for (u32 i = 0; i < nl; ++i) {
    s16 r = st && i < nr ? right[i] : left[i];
    for (int rep = 0; rep < (half ? 2 : 1); ++rep) resample(left[i], r, out);
  }
}

void XaAdpcm::do_state(StateIO& s) {
  s.section("XADP", 1);
  s.pod(hist_);
  s.pod(prev_);
  s.pod(phase_);
  if (s.loading() && phase_ >= 7) s.fail("XA resampler phase out of range");
}

}  // namespace psx
