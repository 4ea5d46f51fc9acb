// SHA-1 (see sha1.h); constants and steps from FIPS 180-4 §4.1.1, §5.3.1 and §6.1.2.
#include "core/sha1.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace psx {

namespace {
u32 rol(u32 x, int n) { return x << n | x >> (32 - n); }
}  // namespace

Sha1::Sha1() : h_{0x67452301u, 0xEFCDAB89u, 0x98BADCFEu, 0x10325476u, 0xC3D2E1F0u} {}

void Sha1::block(const u8* p) {
  u32 w[80];
  for (int t = 0; t < 16; ++t) w[t] = u32{p[4 * t]} << 24 | u32{p[4 * t + 1]} << 16 | u32{p[4 * t + 2]} << 8 | p[4 * t + 3];
  for (int t = 16; t < 80; ++t) w[t] = rol(w[t - 3] ^ w[t - 8] ^ w[t - 14] ^ w[t - 16], 1);
  u32 a = h_[0], b = h_[1], c = h_[2], d = h_[3], e = h_[4];
  for (int t = 0; t < 80; ++t) {
    u32 f, k;
    if (t < 20) f = (b & c) | (~b & d), k = 0x5A827999u;
    else if (t < 40) f = b ^ c ^ d, k = 0x6ED9EBA1u;
    else if (t < 60) f = (b & c) | (b & d) | (c & d), k = 0x8F1BBCDCu;
    else f = b ^ c ^ d, k = 0xCA62C1D6u;
    u32 temp = rol(a, 5) + f + e + k + w[t];
    e = d, d = c, c = rol(b, 30), b = a, a = temp;
  }
  h_[0] += a, h_[1] += b, h_[2] += c, h_[3] += d, h_[4] += e;
}

void Sha1::update(const void* data, size_t n) {
  const u8* p = static_cast<const u8*>(data);
  length_ += n;
  while (n > 0) {
    size_t take = std::min(n, buf_.size() - used_);
    std::memcpy(buf_.data() + used_, p, take);
    used_ += take, p += take, n -= take;
    if (used_ == buf_.size()) block(buf_.data()), used_ = 0;
  }
}

std::string Sha1::hex() {
  // Padding: a 1 bit, zeros to 56 mod 64 bytes, then the message length in bits, big-endian.
  u64 bits = length_ * 8;
  u8 one = 0x80, zero = 0;
  update(&one, 1);
  while (used_ != 56) update(&zero, 1);
  u8 len[8];
  for (int i = 0; i < 8; ++i) len[i] = static_cast<u8>(bits >> (56 - 8 * i));
  update(len, 8);
  char out[41];
  for (int i = 0; i < 5; ++i) std::snprintf(out + 8 * i, 9, "%08x", h_[i]);
  return std::string(out, 40);
}

}  // namespace psx
