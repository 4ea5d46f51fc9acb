// Locating the shared hardware recordings (../shared/testdata) from unit tests.
#pragma once
#include <cstdlib>
#include <filesystem>
#include <string>

namespace psx::test {

inline std::filesystem::path testdata_dir() {
  if (const char* env = std::getenv("PSXRL_TESTDATA")) return env;
  return PSXRL_TESTDATA_DIR;
}

}  // namespace psx::test
