// Save-state container: header, checksum and compression.
#include "core/save_state.h"

#include <zlib.h>

#include <cstring>
#include <stdexcept>

#include "core/hash.h"
#include "core/state.h"

namespace psx {

namespace {
constexpr char kMagic[8] = {'P', 'S', 'X', 'R', 'L', 'S', 'A', 'V'};

void put32(std::vector<u8>& out, u32 v) {
  for (int i = 0; i < 4; ++i) out.push_back(u8(v >> (8 * i)));
}
void put64(std::vector<u8>& out, u64 v) {
  for (int i = 0; i < 8; ++i) out.push_back(u8(v >> (8 * i)));
}
u64 get(const u8* p, int bytes) {
  u64 v = 0;
  for (int i = 0; i < bytes; ++i) v |= u64(p[i]) << (8 * i);
  return v;
}
[[noreturn]] void fail(const std::string& what) { throw StateError("save state: " + what); }
}  // namespace

std::vector<u8> pack_save_state(const SaveStateHeader& h, const std::vector<u8>& payload) {
  std::vector<u8> stored;
  if (h.compressed) {
    uLongf n = compressBound(payload.size());
    stored.resize(n);
    if (compress2(stored.data(), &n, payload.data(), payload.size(), Z_BEST_SPEED) != Z_OK)
      throw std::runtime_error("save state: compression failed");
    stored.resize(n);
  }
  const std::vector<u8>& body = h.compressed ? stored : payload;
  std::vector<u8> out(kMagic, kMagic + 8);
  put32(out, h.version);
  put32(out, h.compressed ? 1 : 0);
  put64(out, h.bios_hash);
  put64(out, h.program_hash);
  put64(out, payload.size());
  put64(out, fnv1a(payload.data(), payload.size()));
  put64(out, body.size());
  out.insert(out.end(), body.begin(), body.end());
  return out;
}

std::vector<u8> unpack_save_state(const u8* d, size_t size, u64 bios_hash, u64 program_hash, u32* format) {
  if (size < 8 || std::memcmp(d, kMagic, 8) != 0) fail("not a psxrl save state (offset 0: expected \"PSXRLSAV\")");
  if (size < SaveStateHeader::kSize) fail("truncated header (" + std::to_string(size) + " of 56 bytes)");
  u32 version = u32(get(d + 8, 4)), flags = u32(get(d + 12, 4));
  if (version > SaveStateHeader::kFormatVersion)
    fail("format version " + std::to_string(version) + " was made by a newer psxrl; this build reads versions " +
         std::to_string(SaveStateHeader::kOldestFormatVersion) + " to " +
         std::to_string(SaveStateHeader::kFormatVersion));
  if (version < SaveStateHeader::kOldestFormatVersion)
    fail("format version " + std::to_string(version) + " is older than this build reads (" +
         std::to_string(SaveStateHeader::kOldestFormatVersion) + " to " +
         std::to_string(SaveStateHeader::kFormatVersion) + ")");
  if (flags > 1) fail("offset 12: unknown flags " + std::to_string(flags));
  if (get(d + 16, 8) != bios_hash) fail("made with a different BIOS than the one loaded");
  if (get(d + 24, 8) != program_hash) fail("made with a different disc or EXE than the one loaded");
  u64 payload_size = get(d + 32, 8), checksum = get(d + 40, 8), stored = get(d + 48, 8);
  if (stored != size - SaveStateHeader::kSize)
    fail("truncated or padded: header says " + std::to_string(stored) + " payload bytes, file has " +
         std::to_string(size - SaveStateHeader::kSize));
  if (payload_size > (u64(1) << 30)) fail("offset 32: implausible payload size");
  std::vector<u8> payload(payload_size);
  const u8* body = d + SaveStateHeader::kSize;
  if (flags & 1) {
    uLongf n = payload_size;
    if (uncompress(payload.data(), &n, body, stored) != Z_OK || n != payload_size) fail("corrupt compressed payload");
  } else {
    if (stored != payload_size) fail("offset 48: stored size differs from payload size");
    if (payload_size) std::memcpy(payload.data(), body, payload_size);  // an empty vector's data() may be null
  }
  if (fnv1a(payload.data(), payload.size()) != checksum) fail("corrupt payload (checksum mismatch)");
  if (format) *format = version;
  return payload;
}

}  // namespace psx
