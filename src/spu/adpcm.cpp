// SPU-ADPCM block decoding and encoding (psx-spx "SPU ADPCM Samples", filter table from
// "CDROM XA-ADPCM": pos_xa_adpcm_table / neg_xa_adpcm_table).
#include "spu/adpcm.h"

#include <algorithm>
#include <array>
#include <limits>

namespace psx::spu {
namespace {

// Prediction weights (in 1/64) for filters 0..4.
constexpr s32 kFilterPos[5] = {0, 60, 115, 98, 122};
constexpr s32 kFilterNeg[5] = {0, 0, -52, -55, -60};

// Shift values 13..15 are reserved and act as shift 9 (psx-spx); filters above 4 do not exist
// in the table and are taken as filter 4 (as other emulators do).
u32 effective_shift(u8 header) {
  u32 shift = header & 0xF;
  return shift > 12 ? 9 : shift;
}
u32 effective_filter(u8 header) { return std::min<u32>((header >> 4) & 7, 4); }

// Sample i of a filter-0 block, with `shift` = 16 + the effective shift: filter 0 predicts
// (0 + 32) >> 6 = 0 and a shifted nibble always fits in 16 bits, so this is the whole sample.
// (nibble << 28) >> (16 + shift) is the signed nibble << 12 >> shift.
s16 filter0_sample(const u8* data, u32 i, u32 shift) {
  const u32 nibble = (data[i / 2] >> ((i & 1) * 4)) & 0xF;
  return static_cast<s16>(static_cast<s32>(nibble << 28) >> shift);
}

// One decoder step: sample = (nibble << 12 >> shift) + (old*pos + older*neg + 32) >> 6.
s16 predict(s32 nibble, u32 shift, u32 filter, const AdpcmHistory& h) {
  s32 s = (nibble * (1 << 12)) >> shift;
  s += (h.old * kFilterPos[filter] + h.older * kFilterNeg[filter] + 32) >> 6;
  return static_cast<s16>(std::clamp(s, -0x8000, 0x7FFF));
}

// Encodes 28 samples with one filter/shift pair; returns the squared error and fills nibbles.
s64 try_encode(const s16* in, u32 shift, u32 filter, AdpcmHistory h, std::array<u8, 28>& nibbles) {
  s64 error = 0;
  for (u32 i = 0; i < kAdpcmBlockSamples; ++i) {
    s32 prediction = (h.old * kFilterPos[filter] + h.older * kFilterNeg[filter] + 32) >> 6;
    s32 residual = in[i] - prediction;
    // Round residual / 2^(12-shift) to nearest, then pick the better of the neighbours after
    // clamping, because the decoder saturates.
    s32 scale = 1 << (12 - shift);
    s32 q = residual >= 0 ? (residual + scale / 2) / scale : -((-residual + scale / 2) / scale);
    q = std::clamp(q, -8, 7);
    s64 best_err = std::numeric_limits<s64>::max();
    s32 best_q = q;
    s16 best_out = 0;
    for (s32 cand = std::max(q - 1, -8); cand <= std::min(q + 1, 7); ++cand) {
      s16 out = predict(cand, shift, filter, h);
      s64 e = static_cast<s64>(out - in[i]) * (out - in[i]);
      if (e < best_err) best_err = e, best_q = cand, best_out = out;
    }
    error += best_err;
    nibbles[i] = static_cast<u8>(best_q & 0xF);
    h.older = h.old;
    h.old = best_out;
  }
  return error;
}

}  // namespace

void decode_adpcm_block(const u8* block, AdpcmHistory& history, s16* out) {
  // The same steps as predict() (nibbles low first), with the weights and the history in
  // registers.
  const u32 shift = 16 + effective_shift(block[0]);
  const u32 filter = effective_filter(block[0]);
  const u8* data = block + 2;
  if (filter == 0) {
    for (u32 i = 0; i < kAdpcmBlockSamples; ++i) out[i] = filter0_sample(data, i, shift);
    history.old = out[kAdpcmBlockSamples - 1];
    history.older = out[kAdpcmBlockSamples - 2];
    return;
  }
  const s32 pos = kFilterPos[filter], neg = kFilterNeg[filter];
  s32 old = history.old, older = history.older;
  for (u32 i = 0; i < kAdpcmBlockSamples; ++i) {
    const u32 nibble = (data[i / 2] >> ((i & 1) * 4)) & 0xF;
    s32 s = static_cast<s32>(nibble << 28) >> shift;
    s = std::clamp(s + ((old * pos + older * neg + 32) >> 6), -0x8000, 0x7FFF);
    out[i] = static_cast<s16>(s);
    older = old;
    old = s;
  }
  history.old = static_cast<s16>(old);
  history.older = static_cast<s16>(older);
}

std::vector<u8> encode_adpcm(const s16* pcm, size_t count, const AdpcmEncodeOptions& options) {
  const size_t blocks = std::max<size_t>(1, (count + kAdpcmBlockSamples - 1) / kAdpcmBlockSamples);
  std::vector<u8> out(blocks * kAdpcmBlockBytes, 0);
  AdpcmHistory h;
  const size_t loop_block = std::min<size_t>(options.loop_start / kAdpcmBlockSamples, blocks - 1);
  for (size_t b = 0; b < blocks; ++b) {
    std::array<s16, kAdpcmBlockSamples> in{};
    for (u32 i = 0; i < kAdpcmBlockSamples; ++i) {
      size_t n = b * kAdpcmBlockSamples + i;
      in[i] = n < count ? pcm[n] : 0;
    }
    s64 best_error = std::numeric_limits<s64>::max();
    u8 best_header = 0;
    std::array<u8, 28> best_nibbles{}, nibbles{};
    for (u32 filter = 0; filter < 5; ++filter) {
      for (u32 shift = 0; shift <= 12; ++shift) {
        s64 e = try_encode(in.data(), shift, filter, h, nibbles);
        if (e < best_error) {
          best_error = e;
          best_header = static_cast<u8>(filter << 4 | shift);
          best_nibbles = nibbles;
        }
      }
    }
    u8* block = &out[b * kAdpcmBlockBytes];
    block[0] = best_header;
    for (u32 i = 0; i < kAdpcmBlockSamples; i += 2) block[2 + i / 2] = static_cast<u8>(best_nibbles[i] | best_nibbles[i + 1] << 4);
    // Replay the chosen encoding so the history matches what the hardware will decode.
    s16 decoded[kAdpcmBlockSamples];
    decode_adpcm_block(block, h, decoded);
    u8 flags = 0;
    if (options.loop && b == loop_block) flags |= kAdpcmLoopStart;
    if (b == blocks - 1) flags |= options.loop ? (kAdpcmLoopEnd | kAdpcmLoopRepeat) : kAdpcmLoopEnd;
    block[1] = flags;
  }
  return out;
}

}  // namespace psx::spu
