// SPU-ADPCM decoding checked against the filter equations worked by hand (psx-spx: sample =
// (nibble << 12 >> shift) + (old*pos + older*neg + 32) >> 6, pos/neg = 0,60,115,98,122 /
// 0,0,-52,-55,-60, shifts 13..15 act as 9, clamped to 16 bits), the encoder's round trip, and the
// block cache answering as the decoder.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "spu/adpcm.h"
#include "spu/adpcm_cache.h"

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

// What decode_adpcm_block() gives for a block and a history.
AdpcmBlockCache::Decoded decoded(const std::vector<u8>& b, AdpcmHistory h) {
  AdpcmBlockCache::Decoded d;
  decode_adpcm_block(b.data(), h, d.samples.data());
  d.history = h;
  return d;
}

bool same(const AdpcmBlockCache::Decoded& a, const AdpcmBlockCache::Decoded& b) {
  return a.samples == b.samples && a.history.old == b.history.old && a.history.older == b.history.older;
}

TEST(SpuAdpcm, BlockCacheDecodesAsTheDecoder) {
  // A 512 KiB sound RAM of random blocks with 3000 histories, met 200,000 times at random
  // addresses (multiples of 8, as voices address blocks): hits, misses and blocks that push each
  // other out of their entry (addresses 16 KiB apart share one).
  std::mt19937 rng(5);
  std::vector<u8> ram(512 * 1024 + 16);
  for (u8& byte : ram) byte = static_cast<u8>(rng());
  std::vector<u32> addresses;
  std::vector<AdpcmHistory> histories;
  for (int k = 0; k < 3000; ++k) {
    addresses.push_back((rng() % (512 * 1024 / 8)) * 8);
    histories.push_back({static_cast<s16>(rng()), static_cast<s16>(rng())});
  }
  AdpcmBlockCache cache;
  for (int n = 0; n < 200000; ++n) {
    const size_t k = rng() % addresses.size();
    const std::vector<u8> b(ram.begin() + addresses[k], ram.begin() + addresses[k] + 16);
    ASSERT_TRUE(same(cache.decode(ram.data(), addresses[k], histories[k]), decoded(b, histories[k]))) << "pair " << k;
  }
}

TEST(SpuAdpcm, BlockCacheTellsKeysInOneEntryApart) {
  // A block (filter 2, so both history samples count) met from a history, then met again with
  // one part of the key changed: the older history sample, a byte of the block's second half (as
  // sound RAM rewritten), a byte of its first half; then a block 16 KiB on (the same entry) from
  // the first history. Each must be decoded, not answered with the samples the entry holds.
  std::mt19937 rng(9);
  std::vector<u8> ram(512 * 1024 + 16);
  for (u8& byte : ram) byte = static_cast<u8>(rng());
  const u32 address = 0x1000;
  ram[address] = 0x24;
  const AdpcmHistory h{1234, -4321};
  const auto block_at = [&](u32 a) { return std::vector<u8>(ram.begin() + a, ram.begin() + a + 16); };
  AdpcmBlockCache cache;
  const std::vector<u8> original = block_at(address);
  ASSERT_TRUE(same(cache.decode(ram.data(), address, h), decoded(original, h)));
  const AdpcmHistory other{1234, 999};
  EXPECT_TRUE(same(cache.decode(ram.data(), address, other), decoded(original, other)));
  EXPECT_FALSE(same(decoded(original, other), decoded(original, h)));  // the change shows
  for (u32 byte : {12u, 5u}) {
    ASSERT_TRUE(same(cache.decode(ram.data(), address, h), decoded(original, h)));
    ram[address + byte] ^= 0x77;
    EXPECT_TRUE(same(cache.decode(ram.data(), address, h), decoded(block_at(address), h))) << "byte " << byte;
    EXPECT_FALSE(same(decoded(block_at(address), h), decoded(original, h)));
    ram[address + byte] ^= 0x77;
  }
  ASSERT_TRUE(same(cache.decode(ram.data(), address, h), decoded(original, h)));
  const u32 twin = address + 16 * 1024;
  EXPECT_TRUE(same(cache.decode(ram.data(), twin, h), decoded(block_at(twin), h)));
}

TEST(SpuAdpcm, BlockInTheLastEightBytesGoesOnAtTheStart) {
  // Sound RAM's last 8 bytes hold the header and 6 data bytes; the block's other 8 data bytes
  // are RAM's first 8 (the address wraps at 512 KiB).
  std::vector<u8> ram(kSoundRamBytes);
  std::mt19937 rng(3);
  for (u8& byte : ram) byte = static_cast<u8>(rng());
  const u32 last = kSoundRamBytes - 8;
  std::vector<u8> b(ram.begin() + last, ram.end());
  b.insert(b.end(), ram.begin(), ram.begin() + 8);
  AdpcmBlockCache cache;
  EXPECT_TRUE(same(cache.decode(ram.data(), last, AdpcmHistory{}), decoded(b, AdpcmHistory{})));
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
