// Reading the reference data kept in the repository (tests/data/, see its README.md): every file
// is gzip-compressed and required; a missing or damaged file is an error for the test to report.
#pragma once
#include <zlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace psx::test {

inline std::filesystem::path testdata_dir() { return PSXRL_TESTDATA_DIR; }

// The whole decompressed content of a .gz file. Throws std::runtime_error naming the file when
// it is missing, unreadable or not valid gzip.
inline std::string read_gz(const std::filesystem::path& path) {
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("test data file missing: " + path.string() +
                             " (it belongs to the repository, see tests/data/README.md)");
  gzFile f = gzopen(path.c_str(), "rb");
  if (!f) throw std::runtime_error("cannot open test data file " + path.string());
  std::string out;
  char buf[1 << 16];
  int n;
  while ((n = gzread(f, buf, sizeof buf)) > 0) out.append(buf, size_t(n));
  // A truncated stream ends the reads without an error from gzread; gzerror and gzclose report it.
  int err = Z_OK;
  const std::string what = gzerror(f, &err);
  const int closed = gzclose(f);
  if (n < 0 || err != Z_OK || closed != Z_OK)
    throw std::runtime_error("cannot decompress test data file: " +
                             (what.empty() ? path.string() + ": truncated gzip stream" : what));
  return out;
}

}  // namespace psx::test
