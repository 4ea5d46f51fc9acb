// Recording a play session from a running console, and replaying one to check that it reproduces
// its snapshots bit for bit. The recorder is driven a frame at a time, so the same code serves a
// person at a window (marks from a key) and an input script played headless.
#pragma once
#include <optional>
#include <string>

#include "core/console.h"
#include "memsearch/session.h"

namespace psxrl::memsearch {

class Recorder {
 public:
  // Starts recording `console` as it is now: its state becomes the session's start state.
  // `interval` frames apart, a snapshot is taken when a frame ends (0: only at marks and the end).
  Recorder(psx::Console& console, SessionSource source, psx::u32 interval);

  // Runs one frame with these buttons held on ports 1 and 2 (pad_button bits).
  void run_frame(psx::u16 pad1, psx::u16 pad2);
  // Records a frame the caller has just run with these buttons held (an environment's move).
  void frame_ran(psx::u16 pad1, psx::u16 pad2);
  // Marks the frame that last ended ("score just went up"); its snapshot is kept.
  void mark(const std::string& label);
  psx::u64 frames() const { return session_.frames; }
  // Ends the recording (the last frame is always snapshotted) and returns the session.
  Session finish();

 private:
  void snapshot();

  psx::Console& console_;
  Session session_;
};

// Boots `console` the way the session's source says (BIOS, disc, EXE), ready for its start state.
void boot_source(psx::Console& console, const SessionSource& source);

// Replays a session on a console booted from its source: loads the start state, presses each
// frame's buttons and compares RAM and scratchpad with every snapshot. Returns the first frame
// whose snapshot differs, or nothing when all match. Throws psx::StateError if the start state
// does not belong to the booted console.
std::optional<psx::u64> replay_session(psx::Console& console, const Session& session);

}  // namespace psxrl::memsearch
