// Atomic file writing, the one implementation for every file the project writes (save states, RAM
// dumps, screenshots, WAV files, memory cards, checkpoints, disc images, EXEs): the bytes go to a
// new temporary file in the target's directory, are flushed to disk, and the temporary file is
// renamed over the target, so a reader or a crash never sees a half-written file (DESIGN.md "Bad
// input is expected").
#pragma once
#include <string>
#include <vector>

#include "core/types.h"

namespace psx {

// Writes `data` to `path` atomically: a temporary file `path.tmp.PID.N` created exclusively (so
// two writers, in two threads or two processes, never share one), written, fsync'ed, renamed over
// `path`, then the directory fsync'ed so the rename itself survives a crash. On failure the
// temporary file is removed, `path` is untouched, and std::runtime_error names the file and the
// reason. Two writers racing for one path leave one of the two contents, whole. Temporary files
// that killed processes left in the folder ("*.tmp.PID.N" whose PID no longer runs) are removed
// first, so an interrupted run leaves no litter behind for good.
void write_file_atomically(const std::string& path, const std::vector<u8>& data);
void write_file_atomically(const std::string& path, const u8* data, size_t size);

}  // namespace psx
