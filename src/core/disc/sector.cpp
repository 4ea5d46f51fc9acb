// EDC and ECC generation for CD-ROM data sectors (ECMA-130 annex A, psx-spx "CDROM Sector
// Encoding"). The ECC is a product code over the bytes from the header onward: P parity
// (RS(26,24)) down 86 columns of the 2064 bytes 0x0C..0x81B, then Q parity (RS(45,43)) along 52
// diagonals of the 2236 bytes 0x0C..0x8C7 (P included), both over GF(2^8) with the field
// polynomial x^8+x^4+x^3+x^2+1.
#include "core/disc/sector.h"

#include <cstring>

#include "core/endian.h"

namespace psx::disc {
namespace {

struct Tables {
  std::array<u32, 256> edc{};
  std::array<u8, 256> mul2{};     // x * alpha in GF(2^8)
  std::array<u8, 256> div3{};     // x / (alpha + 1): inverse of (y ^ y*alpha)
  Tables() {
    for (u32 i = 0; i < 256; ++i) {
      u32 crc = i;
      for (int b = 0; b < 8; ++b) crc = (crc >> 1) ^ ((crc & 1) ? 0xD8018001u : 0);  // 0x8001801B reflected
      edc[i] = crc;
      u32 m = (i << 1) ^ ((i & 0x80) ? 0x11D : 0);
      mul2[i] = static_cast<u8>(m);
      div3[i ^ m] = static_cast<u8>(i);
    }
  }
};

// Built once at first use; read-only afterwards, so sharing between consoles is safe.
const Tables& tables() {
  static const Tables t;
  return t;
}

// One parity pass. Vector `major` takes `minor_count` bytes starting at (major/2)*major_mult +
// (major&1), stepping by `minor_inc` modulo the covered size; its two parity bytes go to
// dest[major] and dest[major + major_count]. Horner evaluation gives the parity for which both
// syndromes (sum of c_k, and sum of c_k * alpha^(n-1-k)) vanish.
void ecc_pass(const u8* src, u32 major_count, u32 minor_count, u32 major_mult, u32 minor_inc, u8* dest) {
  const Tables& t = tables();
  const u32 size = major_count * minor_count;
  for (u32 major = 0; major < major_count; ++major) {
    u32 index = (major >> 1) * major_mult + (major & 1);
    u8 a = 0, b = 0;
    for (u32 minor = 0; minor < minor_count; ++minor) {
      u8 v = src[index];
      index += minor_inc;
      if (index >= size) index -= size;
      a ^= v;
      b ^= v;
      a = t.mul2[a];
    }
    a = t.div3[t.mul2[a] ^ b];
    dest[major] = a;
    dest[major + major_count] = a ^ b;
  }
}

void compute_ecc(u8* raw) {
  ecc_pass(raw + 12, 86, 24, 2, 86, raw + 0x81C);
  ecc_pass(raw + 12, 52, 43, 86, 88, raw + 0x8C8);
}

}  // namespace

bool has_sync(const u8* raw) {
  if (raw[0] != 0 || raw[11] != 0) return false;
  for (int i = 1; i <= 10; ++i)
    if (raw[i] != 0xFF) return false;
  return true;
}

u32 edc(const u8* data, size_t len) {
  const Tables& t = tables();
  u32 crc = 0;
  for (size_t i = 0; i < len; ++i) crc = (crc >> 8) ^ t.edc[(crc ^ data[i]) & 0xFF];
  return crc;
}

void write_sync_header(u8* raw, u32 abs, u8 mode) {
  raw[0] = 0;
  std::memset(raw + 1, 0xFF, 10);
  raw[11] = 0;
  Msf m = Msf::from_sectors(abs);
  raw[12] = to_bcd(m.minute);
  raw[13] = to_bcd(m.second);
  raw[14] = to_bcd(m.sector);
  raw[15] = mode;
}

void finish_mode2_form1(u8* raw) {
  store_le32(raw + 0x818, edc(raw + 16, 0x808));
  u8 header[4];
  std::memcpy(header, raw + 12, 4);
  std::memset(raw + 12, 0, 4);
  compute_ecc(raw);
  std::memcpy(raw + 12, header, 4);
}

void finish_mode2_form2(u8* raw) { store_le32(raw + 0x92C, edc(raw + 16, 0x91C)); }

void finish_mode1(u8* raw) {
  store_le32(raw + 0x810, edc(raw, 0x810));
  std::memset(raw + 0x814, 0, 8);
  compute_ecc(raw);
}

void build_mode2_form1(u8* raw, u32 abs, const u8 subheader[4], const u8* data2048) {
  write_sync_header(raw, abs, 2);
  std::memcpy(raw + 16, subheader, 4);
  std::memcpy(raw + 20, subheader, 4);
  std::memcpy(raw + 24, data2048, kDataSectorSize);
  finish_mode2_form1(raw);
}

}  // namespace psx::disc
