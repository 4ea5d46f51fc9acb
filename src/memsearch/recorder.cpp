// Recorder and replay (recorder.h).
#include "memsearch/recorder.h"

#include <cstring>

namespace psxrl::memsearch {

using psx::u16;
using psx::u32;
using psx::u64;
using psx::u8;

namespace {

void copy_memory(const psx::Console& console, std::vector<u8>& out) {
  out.resize(kSnapshotBytes);
  std::memcpy(out.data(), console.ram().data(), kRamBytes);
  std::memcpy(out.data() + kRamBytes, console.scratchpad().data(), kScratchBytes);
}

}  // namespace

Recorder::Recorder(psx::Console& console, SessionSource source, u32 interval) : console_(console) {
  session_.source = std::move(source);
  session_.snapshot_interval = interval;
  session_.start_state = console.save_state(true);
#ifdef PSXRL_VERSION
  session_.psxrl_version = PSXRL_VERSION;
#endif
}

void Recorder::run_frame(u16 pad1, u16 pad2) {
  console_.set_buttons(1, pad1);
  console_.set_buttons(2, pad2);
  console_.run_frame();
  frame_ran(pad1, pad2);
}

void Recorder::frame_ran(u16 pad1, u16 pad2) {
  session_.pad1.push_back(pad1);
  session_.pad2.push_back(pad2);
  ++session_.frames;
  u32 n = session_.snapshot_interval;
  if (n && (session_.frames - 1) % n == 0) snapshot();
}

void Recorder::snapshot() {
  u64 frame = session_.frames - 1;
  if (!session_.snapshot_frames.empty() && session_.snapshot_frames.back() == frame) return;
  session_.snapshot_frames.push_back(frame);
  copy_memory(console_, session_.snapshots.emplace_back());
}

void Recorder::mark(const std::string& label) {
  if (session_.frames == 0) throw std::logic_error("a mark needs a frame that has ended");
  session_.marks.push_back({session_.frames - 1, label});
  snapshot();
}

Session Recorder::finish() {
  if (session_.frames == 0) throw std::logic_error("a session needs at least one frame");
  snapshot();
  return std::move(session_);
}

void boot_source(psx::Console& console, const SessionSource& source) {
  if (!source.bios.empty()) console.load_bios(source.bios);
  if (!source.disc.empty()) console.insert_disc(source.disc);
  if (!source.exe.empty()) console.boot_exe(source.exe);
  else if (!source.disc.empty()) console.boot_disc();
  else console.boot_bios();
}

std::optional<u64> replay_session(psx::Console& console, const Session& s) {
  console.load_state(s.start_state);
  std::vector<u8> now;
  size_t next = 0;
  for (u64 f = 0; f < s.frames && next < s.snapshots.size(); ++f) {
    console.set_buttons(1, s.pad1[f]);
    console.set_buttons(2, s.pad2[f]);
    console.run_frame();
    if (s.snapshot_frames[next] != f) continue;
    copy_memory(console, now);
    if (now != s.snapshots[next]) return f;
    ++next;
  }
  return std::nullopt;
}

}  // namespace psxrl::memsearch
