// The summary `psxrl run` prints when a run ends (standard error, not under --quiet): frames
// run, files written and, when the program is a game integration's built-in EXE, that game's
// level, score and outcome read through the integration (games/<name>/game.toml).
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "core/console.h"

namespace psxrl::cli {

// `exe` is the --exe path (empty for a disc or BIOS run); `written` the files the run wrote.
void print_run_summary(std::FILE* out, const psx::Console& console, const std::string& exe,
                       const std::vector<std::string>& written);

}  // namespace psxrl::cli
