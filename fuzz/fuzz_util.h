// Helpers shared by the fuzz targets: a tiny in-memory PS-X EXE for consoles that need a
// program, a little-endian reader over the fuzz input, and a private scratch folder for the
// parsers that only read files. Nothing here keeps mutable state between inputs except the
// scratch folder's path, which is fixed for the life of the process.
#pragma once
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/types.h"

namespace psxfuzz {

using psx::u32;
using psx::u8;

// A PS-X EXE whose text (padded with zeros, i.e. NOPs, to a multiple of 2048 bytes) loads and
// starts at 0x80010000, with the stack at the top of RAM.
inline std::vector<u8> make_exe(const std::vector<u8>& text) {
  const u32 size = std::max<u32>(2048, static_cast<u32>((text.size() + 2047) / 2048 * 2048));
  std::vector<u8> f(2048 + size, 0);
  std::memcpy(f.data(), "PS-X EXE", 8);
  auto put = [&](u32 off, u32 v) {
    for (int i = 0; i < 4; ++i) f[off + i] = static_cast<u8>(v >> (8 * i));
  };
  put(0x10, 0x80010000);  // pc
  put(0x18, 0x80010000);  // text address
  put(0x1C, size);
  put(0x30, 0x801FFF00);  // stack base
  if (!text.empty()) std::memcpy(f.data() + 2048, text.data(), text.size());
  return f;
}

// Consumes the fuzz input front to back; reads past the end give zeros.
class Reader {
 public:
  Reader(const u8* data, size_t size) : p_(data), n_(size) {}
  bool empty() const { return n_ == 0; }
  size_t left() const { return n_; }
  u8 byte() {
    if (!n_) return 0;
    --n_;
    return *p_++;
  }
  u32 u16() {
    const u32 lo = byte();
    return lo | u32(byte()) << 8;
  }
  u32 word() {
    u32 v = 0;
    for (int i = 0; i < 4; ++i) v |= u32(byte()) << (8 * i);
    return v;
  }
  std::vector<u8> rest() {
    std::vector<u8> v(p_, p_ + n_);
    p_ += n_;
    n_ = 0;
    return v;
  }

 private:
  const u8* p_;
  size_t n_;
};

// A folder of this process's own under the system temp folder (parallel fuzzing jobs get one
// each), created on first use and removed at exit.
inline const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    std::string tmpl = (std::filesystem::temp_directory_path() / "psxrl-fuzz-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) std::abort();
    static std::string keep = tmpl;
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(keep, ec);
    });
    return std::filesystem::path(tmpl);
  }();
  return dir;
}

inline void write_file(const std::filesystem::path& p, const void* data, size_t size) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) std::abort();  // the harness itself failed, not the parser
}

}  // namespace psxfuzz
