// A recorded play session (`psxrl record`), the raw material of `psxrl memsearch`: the start
// state, every frame's pad input, RAM snapshots at an interval and at the player's marks. A
// session replays deterministically from its start state, so its snapshots can always be checked.
//
// On disk, a session is a folder:
//   session.toml   manifest: format, psxrl version, what was booted, frames, interval, marks
//   start.state    the console's save state when recording began (compressed)
//   inputs.bin     "PSXRLINP", u32 format, u64 frames, then per frame u16 port 1 + u16 port 2
//                  buttons (pad_button bits), the per-frame part zlib-compressed
//   snapshots.bin  "PSXRLSNP", u32 format, u32 count, u32 snapshot size, then per snapshot:
//                  u64 frame, u32 stored size, zlib(snapshot XOR previous snapshot)
// A snapshot is main RAM (2 MiB) followed by the scratchpad (1 KiB), taken when its frame ends.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/types.h"

namespace psxrl::memsearch {

// What the session's console booted, so a replay can boot the same (paths as given, absolute).
struct SessionSource {
  std::string exe, disc, bios;
  std::string game;  // the integration it was recorded through, if any
};

struct Mark {
  psx::u64 frame = 0;  // the mark's snapshot is taken when this frame ends
  std::string label;
};

// Guest addresses of the bytes a snapshot holds.
constexpr psx::u32 kRamBytes = 2 * 1024 * 1024;
constexpr psx::u32 kScratchBytes = 1024;
constexpr psx::u32 kSnapshotBytes = kRamBytes + kScratchBytes;
constexpr psx::u32 kRamBase = 0x80000000, kScratchBase = 0x1F800000;
// Snapshot offset <-> guest address (KSEG0 for RAM); address_to_offset returns false outside.
psx::u32 offset_to_address(psx::u32 offset);
bool address_to_offset(psx::u32 address, psx::u32& offset);

struct Session {
  static constexpr psx::u32 kFormat = 1;
  std::string dir;  // where it was read from or will be written to
  std::string psxrl_version;
  SessionSource source;
  psx::u64 frames = 0;             // frames recorded
  psx::u32 snapshot_interval = 0;  // frames between periodic snapshots (0: marks only)
  std::vector<Mark> marks;         // ascending frame order
  std::vector<psx::u8> start_state;
  // Per frame: buttons on ports 1 and 2 while the frame ran.
  std::vector<psx::u16> pad1, pad2;
  // Snapshots in ascending frame order; snapshot_frames[i] is when snapshots[i] was taken.
  std::vector<psx::u64> snapshot_frames;
  std::vector<std::vector<psx::u8>> snapshots;

  // The snapshot taken when `frame` ended; -1 if none was.
  long snapshot_at(psx::u64 frame) const;
};

// Writes a session folder (creating it; every file written atomically). Throws
// std::runtime_error naming the file when it cannot be written.
void write_session(const Session& s, const std::string& dir);
// Reads a session folder. Throws psx::InputError naming the file, the position and what was
// expected for a missing, truncated or inconsistent session.
Session read_session(const std::string& dir);

}  // namespace psxrl::memsearch
