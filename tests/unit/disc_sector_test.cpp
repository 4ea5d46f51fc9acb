// EDC/ECC of built Mode 2 Form 1 sectors, checked against independent bitwise implementations of
// the documented codes (psx-spx "CDROM Sector Encoding", ECMA-130 annex A): EDC is CRC-32 with
// polynomial 0x8001801B processed LSB first; ECC is P (RS(26,24), 86 columns) and Q (RS(45,43),
// 52 diagonals) parity over GF(2^8) with field polynomial 0x11D, header bytes taken as zero.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "core/disc/sector.h"

namespace psx::disc {
namespace {

// Reflect the documented polynomial bit by bit rather than writing down the reflected constant.
u32 reflected_edc_polynomial() {
  u32 p = 0x8001801B, r = 0;
  for (int i = 0; i < 32; ++i) r |= ((p >> i) & 1u) << (31 - i);
  return r;
}

u32 bitwise_edc(const u8* d, size_t n) {
  const u32 poly = reflected_edc_polynomial();
  u32 crc = 0;
  for (size_t i = 0; i < n; ++i) {
    crc ^= d[i];
    for (int b = 0; b < 8; ++b) crc = (crc & 1) ? (crc >> 1) ^ poly : crc >> 1;
  }
  return crc;
}

// GF(2^8) multiply by shift-and-add, reducing by x^8+x^4+x^3+x^2+1.
u8 gf_mul(u8 a, u8 b) {
  u32 r = 0, x = a;
  for (int i = 0; i < 8; ++i) {
    if (b & (1 << i)) r ^= x;
    x <<= 1;
    if (x & 0x100) x ^= 0x11D;
  }
  return static_cast<u8>(r);
}

// Both syndromes of a codeword c_0..c_{n-1}: sum c_k and sum c_k * alpha^(n-1-k), alpha = 2.
std::pair<u8, u8> syndromes(const std::vector<u8>& c) {
  u8 s0 = 0, s1 = 0;
  for (size_t k = 0; k < c.size(); ++k) {
    u8 w = 1;
    for (size_t e = 0; e < c.size() - 1 - k; ++e) w = gf_mul(w, 2);
    s0 ^= c[k];
    s1 ^= gf_mul(c[k], w);
  }
  return {s0, s1};
}

RawSector make_sector(u32 abs, u8 seed) {
  u8 data[kDataSectorSize];
  u32 x = seed * 2654435761u + 1;
  for (u8& b : data) b = static_cast<u8>((x = x * 1103515245u + 12345u) >> 16);
  const u8 sub[4] = {1, 2, kSubmodeData, 0};
  RawSector s{};
  build_mode2_form1(s.data(), abs, sub, data);
  return s;
}

TEST(DiscSector, SyncAndHeaderAreBcdMsf) {
  RawSector s = make_sector(166, 1);  // 166 sectors = 00:02:16
  const u8 sync[12] = {0, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0};
  EXPECT_EQ(0, memcmp(s.data(), sync, 12));
  EXPECT_EQ(s[12], 0x00);
  EXPECT_EQ(s[13], 0x02);
  EXPECT_EQ(s[14], 0x16);
  EXPECT_EQ(s[15], 2);
  RawSector t = make_sector(60 * 75 * 12 + 34 * 75 + 74, 1);  // 12:34:74
  EXPECT_EQ(t[12], 0x12);
  EXPECT_EQ(t[13], 0x34);
  EXPECT_EQ(t[14], 0x74);
  // Subheader written twice.
  EXPECT_EQ(s[16], 1);
  EXPECT_EQ(s[20], 1);
  EXPECT_EQ(s[18], kSubmodeData);
  EXPECT_EQ(s[22], kSubmodeData);
}

TEST(DiscSector, EdcMatchesBitwiseCrc) {
  EXPECT_EQ(reflected_edc_polynomial(), 0xD8018001u);
  for (u8 seed : {1, 2, 3}) {
    RawSector s = make_sector(150 + seed, seed);
    u32 stored = s[0x818] | s[0x819] << 8 | s[0x81A] << 16 | static_cast<u32>(s[0x81B]) << 24;
    EXPECT_EQ(stored, bitwise_edc(s.data() + 16, 0x808)) << "seed " << int(seed);
  }
  const u8 single = 0x01;  // CRC of one byte 0x01 = the reflected polynomial shifted 7 times.
  u32 expect = 1;
  for (int b = 0; b < 8; ++b) expect = (expect & 1) ? (expect >> 1) ^ 0xD8018001u : expect >> 1;
  EXPECT_EQ(edc(&single, 1), expect);
}

TEST(DiscSector, EccPAndQSyndromesVanish) {
  for (u8 seed : {7, 8}) {
    RawSector s = make_sector(150 + 1000 * seed, seed);
    std::memset(s.data() + 12, 0, 4);  // Mode 2: the header is excluded (taken as zero)
    const u8* base = s.data() + 12;
    for (u32 col = 0; col < 86; ++col) {
      std::vector<u8> c;
      for (u32 row = 0; row < 26; ++row) c.push_back(base[col + 86 * row]);
      auto [s0, s1] = syndromes(c);
      ASSERT_EQ(s0, 0) << "P column " << col;
      ASSERT_EQ(s1, 0) << "P column " << col;
    }
    for (u32 d = 0; d < 26; ++d) {
      for (u32 plane = 0; plane < 2; ++plane) {
        std::vector<u8> c;
        for (u32 m = 0; m < 43; ++m) c.push_back(base[(86 * d + plane + 88 * m) % 2236]);
        c.push_back(base[2236 + 2 * d + plane]);
        c.push_back(base[2236 + 52 + 2 * d + plane]);
        auto [s0, s1] = syndromes(c);
        ASSERT_EQ(s0, 0) << "Q diagonal " << d << " plane " << plane;
        ASSERT_EQ(s1, 0) << "Q diagonal " << d << " plane " << plane;
      }
    }
  }
}

TEST(DiscSector, CorruptedDataBreaksTheChecks) {
  RawSector s = make_sector(200, 5);
  s[100] ^= 0x40;
  u32 stored = s[0x818] | s[0x819] << 8 | s[0x81A] << 16 | static_cast<u32>(s[0x81B]) << 24;
  EXPECT_NE(stored, bitwise_edc(s.data() + 16, 0x808));
}

TEST(DiscSector, BcdHelpers) {
  EXPECT_EQ(to_bcd(59), 0x59);
  EXPECT_EQ(from_bcd(0x74), 74u);
  EXPECT_FALSE(valid_bcd(0x1A));
  EXPECT_EQ(Msf::from_sectors(150).second, 2);
  EXPECT_EQ((Msf{1, 2, 3}.to_sectors()), 60u * 75 + 2 * 75 + 3);
}

}  // namespace
}  // namespace psx::disc
