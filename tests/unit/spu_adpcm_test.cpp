// SPU-ADPCM decoding checked against the filter equations worked by hand (psx-spx: sample =
// (nibble << 12 >> shift) + (old*pos + older*neg + 32) >> 6, pos/neg = 0,60,115,98,122 /
// 0,0,-52,-55,-60, shifts 13..15 act as 9, clamped to 16 bits), and the encoder's round trip.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "spu/adpcm.h"

using namespace psx;
using namespace psx::spu;

namespace {
std::vector<u8> block(u8 header, std::vector<u8> data) {
  std::vector<u8> b(16, 0);
  b[0] = header;
  for (size_t i = 0; i < data.size(); ++i) b[2 + i] = data[i];
  return b;
}
}  // namespace

TEST(SpuAdpcm, Filter0IsTheShiftedNibbleAndSetsTheHistory) {
  // Filter 0 (pos 0, neg 0): (0 + 32) >> 6 = 0 is added, so each sample is nibble * 4096 >> shift,
  // whatever the history. Shift 3: nibbles 7, -8, -1, 1 (low first) give 3584, -4096, -512, 512;
  // the last two nibbles -1 (0xF) and -7 (0x9) become the history (old = the last sample).
  auto b = block(0x03, {0x87, 0x1F, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x9F});
  AdpcmHistory h{1000, -2000};
  s16 out[28];
  decode_adpcm_block(b.data(), h, out);
  EXPECT_EQ(out[0], 3584);
  EXPECT_EQ(out[1], -4096);
  EXPECT_EQ(out[2], -512);
  EXPECT_EQ(out[3], 512);
  EXPECT_EQ(out[4], 0);
  EXPECT_EQ(out[26], -512);
  EXPECT_EQ(out[27], -3584);
  EXPECT_EQ(h.old, -3584);
  EXPECT_EQ(h.older, -512);
  // Shift 12: -8 * 4096 >> 12 = -8 and -1 * 4096 >> 12 = -1 (the shift rounds down); reserved
  // shift 13 acts as 9: -8 * 4096 >> 9 = -64, 7 * 4096 >> 9 = 56.
  decode_adpcm_block(block(0x0C, {0xF8}).data(), h, out);
  EXPECT_EQ(out[0], -8);
  EXPECT_EQ(out[1], -1);
  decode_adpcm_block(block(0x0D, {0x78}).data(), h, out);
  EXPECT_EQ(out[0], -64);
  EXPECT_EQ(out[1], 56);
  EXPECT_EQ(h.old, 0);
  EXPECT_EQ(h.older, 0);
}

TEST(SpuAdpcm, BlockEndDecodesTheLastThreeSamplesAndTheHistory) {
  // Filter 0, shift 2: nibble * 1024. The last three nibbles, samples 25..27, are the high one of
  // byte 12 (-3, 0xD) and both of byte 13 (5, then -8): -3072, 5120, -8192. Samples 0..24 are left
  // as they were (here 77), and the history is the last two samples, as decode_adpcm_block() sets it.
  auto b = block(0x02, {0x11, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xD0, 0x85});
  AdpcmHistory h{1000, -2000};
  s16 out[28];
  std::fill(std::begin(out), std::end(out), s16{77});
  decode_adpcm_block_end(b.data(), h, out);
  EXPECT_EQ(out[0], 77);
  EXPECT_EQ(out[24], 77);
  EXPECT_EQ(out[25], -3072);
  EXPECT_EQ(out[26], 5120);
  EXPECT_EQ(out[27], -8192);
  EXPECT_EQ(h.old, -8192);
  EXPECT_EQ(h.older, 5120);
  // Any other filter links every sample to the ones before: the whole block is decoded. Filter 1,
  // shift 2, nibble 1 then zeros from history 0: 1024, then each sample (old*60 + 32) >> 6.
  auto c = block(0x12, {0x01});
  AdpcmHistory h2;
  std::fill(std::begin(out), std::end(out), s16{77});
  decode_adpcm_block_end(c.data(), h2, out);
  EXPECT_EQ(out[0], 1024);
  EXPECT_EQ(out[1], 960);  // (1024*60 + 32) >> 6 = 61472 >> 6
  EXPECT_EQ(out[2], 900);  // (960*60 + 32) >> 6 = 57632 >> 6
  EXPECT_EQ(h2.old, out[27]);
  EXPECT_EQ(h2.older, out[26]);
}

TEST(SpuAdpcm, Filter1ByHand) {
  // Filter 1 (pos 60), shift 2: each nibble contributes nibble * 4096 >> 2 = nibble * 1024.
  // Nibbles, low first: 1, 2, -1 (0xF), then zeros.
  auto b = block(0x12, {0x21, 0x0F});
  AdpcmHistory h;
  s16 out[28];
  decode_adpcm_block(b.data(), h, out);
  EXPECT_EQ(out[0], 1024);                    // 1024 + (0 + 32) >> 6 = 1024 + 0
  EXPECT_EQ(out[1], 2048 + 960);              // (1024*60 + 32) >> 6 = 61472 >> 6 = 960
  EXPECT_EQ(out[2], -1024 + 2820);            // (3008*60 + 32) >> 6 = 180512 >> 6 = 2820
  EXPECT_EQ(out[3], 1684);                    // (1796*60 + 32) >> 6 = 107792 >> 6 = 1684
  EXPECT_EQ(out[4], 1579);                    // (1684*60 + 32) >> 6 = 101072 >> 6 = 1579
  EXPECT_EQ(h.old, out[27]);
  EXPECT_EQ(h.older, out[26]);
}

TEST(SpuAdpcm, Filter2And4UseTheHistoryAndRoundDown) {
  // Filter 2 (115, -52), shift 12: nibble 7 contributes 7.
  auto b = block(0x2C, {0x07});
  AdpcmHistory h{100, 50};
  s16 out[28];
  decode_adpcm_block(b.data(), h, out);
  EXPECT_EQ(out[0], 7 + 139);  // (100*115 - 50*52 + 32) >> 6 = 8932 >> 6 = 139
  // Negative predictions shift arithmetically: filter 1, old = -100:
  // (-6000 + 32) >> 6 = -5968 >> 6 = floor(-93.25) = -94.
  auto c = block(0x1C, {});
  AdpcmHistory h2{-100, 0};
  decode_adpcm_block(c.data(), h2, out);
  EXPECT_EQ(out[0], -94);
  // Filter 4 (122, -60), shift 0, nibble 7: 7 << 12 = 28672, plus (32767*122 + 32) >> 6 = 62462,
  // clamped to 32767.
  auto d = block(0x40, {0x07});
  AdpcmHistory h3{32767, 0};
  decode_adpcm_block(d.data(), h3, out);
  EXPECT_EQ(out[0], 32767);
}

TEST(SpuAdpcm, Filter3ByHand) {
  // Filter 3 (98, -55), shift 4: nibble -8 (0x8) gives -8 * 4096 >> 4 = -2048.
  auto b = block(0x34, {0x08});
  AdpcmHistory h{1000, 2000};
  s16 out[28];
  decode_adpcm_block(b.data(), h, out);
  EXPECT_EQ(out[0], -2048 - 187);  // (98000 - 110000 + 32) >> 6 = -11968 >> 6 = -187 exactly
}

TEST(SpuAdpcm, ReservedShiftsActAsNine) {
  // Shift 13 acts as 9: nibble 1 gives 4096 >> 9 = 8; nibble -1 gives -4096 >> 9 = -8.
  for (u8 shift : {13, 14, 15}) {
    auto b = block(shift, {0xF1});
    AdpcmHistory h;
    s16 out[28];
    decode_adpcm_block(b.data(), h, out);
    EXPECT_EQ(out[0], 8) << int(shift);
    EXPECT_EQ(out[1], -8) << int(shift);
  }
}

TEST(SpuAdpcm, EncoderRoundTripAndFlags) {
  std::vector<s16> pcm(28 * 10);
  for (size_t i = 0; i < pcm.size(); ++i) pcm[i] = static_cast<s16>(12000 * std::sin(2 * M_PI * i / 37.0));
  auto oneshot = encode_adpcm(pcm.data(), pcm.size(), {});
  ASSERT_EQ(oneshot.size(), 160u);
  for (int b = 0; b < 9; ++b) EXPECT_EQ(oneshot[b * 16 + 1], 0) << b;
  EXPECT_EQ(oneshot[9 * 16 + 1], kAdpcmLoopEnd);  // End+Mute

  AdpcmEncodeOptions loop;
  loop.loop = true;
  loop.loop_start = 28 * 3 + 5;
  auto looped = encode_adpcm(pcm.data(), pcm.size(), loop);
  EXPECT_EQ(looped[3 * 16 + 1], kAdpcmLoopStart);
  EXPECT_EQ(looped[9 * 16 + 1], kAdpcmLoopEnd | kAdpcmLoopRepeat);

  // The decoded sound stays close to the input: 4-bit ADPCM of a smooth sine is better than
  // 1% of full scale RMS.
  AdpcmHistory h;
  double err2 = 0;
  for (int b = 0; b < 10; ++b) {
    s16 out[28];
    decode_adpcm_block(&oneshot[b * 16], h, out);
    for (int i = 0; i < 28; ++i) err2 += std::pow(out[i] - pcm[b * 28 + i], 2);
  }
  EXPECT_LT(std::sqrt(err2 / pcm.size()), 327.0);
  // Padding: 29 samples need two blocks; nothing needs one block.
  EXPECT_EQ(encode_adpcm(pcm.data(), 29, {}).size(), 32u);
  EXPECT_EQ(encode_adpcm(nullptr, 0, {}).size(), 16u);
}
