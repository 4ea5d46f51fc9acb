// Atomic file writing for every output the project produces (save states, RAM dumps, WAV files,
// disc images, ADPCM blocks): the bytes go to a temporary file that is renamed over the target,
// so a failed write never leaves a half-written file (DESIGN.md "Bad input is expected").
#pragma once
#include <string>
#include <vector>

#include "core/types.h"

namespace psx {

// Writes `data` to `path` atomically (temporary file `path.tmp`, then rename); throws
// std::runtime_error naming the file and the reason.
void write_file_atomically(const std::string& path, const std::vector<u8>& data);

}  // namespace psx
