// Tumble's manifest as text, and a one-place edit of it, for tests that build variants of the
// integration (a different move rule, level start or script) without a folder of their own.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"

inline std::string tumble_manifest() {
  auto bytes = psx::read_file(PSXRL_SOURCE_DIR "/games/tumble/game.toml");
  return std::string(bytes.begin(), bytes.end());
}

// `s` with the first `from` replaced by `to`; a `from` not found fails the test.
inline std::string replace(std::string s, const std::string& from, const std::string& to) {
  size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? s : s.replace(at, from.size(), to);
}
