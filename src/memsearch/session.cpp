// Reading and writing session folders (session.h has the layout). Every reader check names the
// file, the byte offset or manifest line, and what was expected.
#include "memsearch/session.h"

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <toml++/toml.h>

#include "core/atomic_file.h"
#include "core/input_error.h"

namespace psxrl::memsearch {

using psx::InputError;
using psx::u16;
using psx::u32;
using psx::u64;
using psx::u8;

namespace {

constexpr char kInputsMagic[8] = {'P', 'S', 'X', 'R', 'L', 'I', 'N', 'P'};
constexpr char kSnapsMagic[8] = {'P', 'S', 'X', 'R', 'L', 'S', 'N', 'P'};
constexpr u64 kMaxFrames = 1ull << 32;        // about 2 years of play at 60 frames per second
constexpr u32 kMaxSnapshots = 1u << 20;

void put32(std::vector<u8>& out, u32 v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<u8>(v >> (8 * i)));
}
void put64(std::vector<u8>& out, u64 v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<u8>(v >> (8 * i)));
}

std::vector<u8> deflate_bytes(const std::vector<u8>& in) {
  uLongf n = compressBound(in.size());
  std::vector<u8> out(n);
  if (compress2(out.data(), &n, in.data(), in.size(), Z_BEST_SPEED) != Z_OK)
    throw std::runtime_error("zlib compression failed");
  out.resize(n);
  return out;
}

// A cursor over one file's bytes that names the file and offset in every error.
class Reader {
 public:
  Reader(std::string file, const std::vector<u8>& data) : file_(std::move(file)), data_(data) {}
  [[noreturn]] void fail(const std::string& what) const { throw InputError::at_offset(file_, pos_, what); }
  const u8* take(size_t n, const char* what) {
    if (n > data_.size() - pos_) fail(std::string("file ends early: expected ") + what);
    const u8* p = data_.data() + pos_;
    pos_ += n;
    return p;
  }
  u32 u32le(const char* what) {
    const u8* p = take(4, what);
    return p[0] | p[1] << 8 | p[2] << 16 | static_cast<u32>(p[3]) << 24;
  }
  u64 u64le(const char* what) {
    u64 lo = u32le(what);
    return lo | static_cast<u64>(u32le(what)) << 32;
  }
  void magic(const char (&m)[8], const char* kind) {
    if (std::memcmp(take(8, kind), m, 8) != 0) {
      pos_ = 0;
      fail(std::string("not a ") + kind + " (expected the magic '" + std::string(m, 8) + "')");
    }
  }
  void format(u32 expected) {
    u32 v = u32le("the format number");
    if (v != expected)
      fail("format " + std::to_string(v) + " is not one this psxrl reads (it reads " + std::to_string(expected) + ")");
  }
  std::vector<u8> inflate(size_t stored, size_t expected_size, const char* what) {
    const u8* p = take(stored, what);
    std::vector<u8> out(expected_size);
    uLongf n = expected_size;
    if (uncompress(out.data(), &n, p, stored) != Z_OK || n != expected_size)
      fail(std::string("corrupt compressed ") + what);
    return out;
  }
  bool at_end() const { return pos_ == data_.size(); }
  size_t pos() const { return pos_; }

 private:
  std::string file_;
  const std::vector<u8>& data_;
  size_t pos_ = 0;
};

std::vector<u8> encode_inputs(const Session& s) {
  std::vector<u8> raw;
  raw.reserve(s.frames * 4);
  for (u64 f = 0; f < s.frames; ++f) {
    for (u16 b : {s.pad1[f], s.pad2[f]}) {
      raw.push_back(static_cast<u8>(b));
      raw.push_back(static_cast<u8>(b >> 8));
    }
  }
  std::vector<u8> out(kInputsMagic, kInputsMagic + 8);
  put32(out, Session::kFormat);
  put64(out, s.frames);
  std::vector<u8> packed = deflate_bytes(raw);
  out.insert(out.end(), packed.begin(), packed.end());
  return out;
}

void decode_inputs(const std::string& file, const std::vector<u8>& data, Session& s) {
  Reader r(file, data);
  r.magic(kInputsMagic, "session input file");
  r.format(Session::kFormat);
  u64 frames = r.u64le("the frame count");
  if (frames != s.frames)
    r.fail("holds " + std::to_string(frames) + " frames, session.toml says " + std::to_string(s.frames));
  std::vector<u8> raw = r.inflate(data.size() - r.pos(), frames * 4, "input data");
  s.pad1.resize(frames);
  s.pad2.resize(frames);
  for (u64 f = 0; f < frames; ++f) {
    s.pad1[f] = static_cast<u16>(raw[f * 4] | raw[f * 4 + 1] << 8);
    s.pad2[f] = static_cast<u16>(raw[f * 4 + 2] | raw[f * 4 + 3] << 8);
  }
}

std::vector<u8> encode_snapshots(const Session& s) {
  std::vector<u8> out(kSnapsMagic, kSnapsMagic + 8);
  put32(out, Session::kFormat);
  put32(out, static_cast<u32>(s.snapshots.size()));
  put32(out, kSnapshotBytes);
  std::vector<u8> delta(kSnapshotBytes);
  for (size_t i = 0; i < s.snapshots.size(); ++i) {
    const std::vector<u8>& cur = s.snapshots[i];
    for (u32 b = 0; b < kSnapshotBytes; ++b) delta[b] = cur[b] ^ (i ? s.snapshots[i - 1][b] : 0);
    std::vector<u8> packed = deflate_bytes(delta);
    put64(out, s.snapshot_frames[i]);
    put32(out, static_cast<u32>(packed.size()));
    out.insert(out.end(), packed.begin(), packed.end());
  }
  return out;
}

void decode_snapshots(const std::string& file, const std::vector<u8>& data, Session& s) {
  Reader r(file, data);
  r.magic(kSnapsMagic, "session snapshot file");
  r.format(Session::kFormat);
  u32 count = r.u32le("the snapshot count");
  if (count == 0 || count > kMaxSnapshots) r.fail("snapshot count " + std::to_string(count) + " is not in 1.." + std::to_string(kMaxSnapshots));
  u32 size = r.u32le("the snapshot size");
  if (size != kSnapshotBytes)
    r.fail("snapshot size " + std::to_string(size) + ", expected " + std::to_string(kSnapshotBytes) + " (RAM + scratchpad)");
  for (u32 i = 0; i < count; ++i) {
    u64 frame = r.u64le("a snapshot's frame");
    if (frame >= s.frames) r.fail("snapshot frame " + std::to_string(frame) + " is past the session's last frame");
    if (i && frame <= s.snapshot_frames.back()) r.fail("snapshot frames must increase");
    bool marked = std::any_of(s.marks.begin(), s.marks.end(), [&](const Mark& m) { return m.frame == frame; });
    bool periodic = s.snapshot_interval && frame % s.snapshot_interval == 0;
    if (!marked && !periodic && frame != s.frames - 1)
      r.fail("snapshot at frame " + std::to_string(frame) + " is neither periodic, at a mark, nor the last frame");
    u32 stored = r.u32le("a snapshot's stored size");
    std::vector<u8> snap = r.inflate(stored, kSnapshotBytes, "snapshot");
    if (i)
      for (u32 b = 0; b < kSnapshotBytes; ++b) snap[b] ^= s.snapshots.back()[b];
    s.snapshot_frames.push_back(frame);
    s.snapshots.push_back(std::move(snap));
  }
  if (!r.at_end()) r.fail("unexpected bytes after the last snapshot");
}

std::string manifest_text(const Session& s) {
  toml::table source{{"exe", s.source.exe}, {"disc", s.source.disc}, {"bios", s.source.bios}, {"game", s.source.game}};
  toml::array marks;
  for (const Mark& m : s.marks)
    marks.push_back(toml::table{{"frame", static_cast<int64_t>(m.frame)}, {"label", m.label}});
  toml::table t{{"format", static_cast<int64_t>(Session::kFormat)},
                {"psxrl_version", s.psxrl_version},
                {"frames", static_cast<int64_t>(s.frames)},
                {"snapshot_interval", static_cast<int64_t>(s.snapshot_interval)},
                {"source", source}};
  if (!marks.empty()) t.insert("marks", marks);
  std::ostringstream out;
  out << "# A psxrl play session (psxrl record); see docs/memsearch.md.\n" << t << "\n";
  return out.str();
}

// The manifest's fields, each checked with the line it is on.
void read_manifest(const std::string& file, Session& s) {
  toml::table t;
  try {
    t = toml::parse_file(file);
  } catch (const toml::parse_error& e) {
    throw InputError::at_line(file, e.source().begin.line, std::string(e.description()));
  }
  auto line_of = [&](const toml::node* n) { return n ? static_cast<u64>(n->source().begin.line) : 1; };
  auto need_int = [&](const toml::table& tab, const char* key, int64_t lo, int64_t hi) {
    const toml::node* n = tab.get(key);
    if (!n || !n->is_integer())
      throw InputError::at_line(file, line_of(n ? n : &tab), std::string("'") + key + "' must be an integer");
    int64_t v = n->as_integer()->get();
    if (v < lo || v > hi)
      throw InputError::at_line(file, line_of(n), std::string("'") + key + "' must be in " + std::to_string(lo) + ".." +
                                                      std::to_string(hi) + ", got " + std::to_string(v));
    return v;
  };
  auto opt_str = [&](const toml::table& tab, const char* key) {
    const toml::node* n = tab.get(key);
    if (!n) return std::string();
    if (!n->is_string()) throw InputError::at_line(file, line_of(n), std::string("'") + key + "' must be a string");
    return n->as_string()->get();
  };
  int64_t format = need_int(t, "format", 0, INT64_MAX);
  if (format != Session::kFormat)
    throw InputError::at_line(file, line_of(t.get("format")),
                              "session format " + std::to_string(format) + " is not one this psxrl reads (1)");
  s.psxrl_version = opt_str(t, "psxrl_version");
  s.frames = static_cast<u64>(need_int(t, "frames", 1, static_cast<int64_t>(kMaxFrames)));
  s.snapshot_interval = static_cast<u32>(need_int(t, "snapshot_interval", 0, UINT32_MAX));
  if (const toml::table* src = t["source"].as_table()) {
    s.source = {opt_str(*src, "exe"), opt_str(*src, "disc"), opt_str(*src, "bios"), opt_str(*src, "game")};
  } else {
    throw InputError::at_line(file, 1, "a [source] table is required");
  }
  const toml::node* marks = t.get("marks");
  if (!marks) return;
  if (marks->is_array() && marks->as_array()->empty()) return;
  if (!marks->is_array_of_tables()) throw InputError::at_line(file, line_of(marks), "'marks' must be an array of tables");
  for (const toml::node& n : *marks->as_array()) {
    const toml::table& m = *n.as_table();
    Mark mark{static_cast<u64>(need_int(m, "frame", 0, static_cast<int64_t>(s.frames) - 1)), opt_str(m, "label")};
    if (mark.label.empty()) throw InputError::at_line(file, line_of(&n), "a mark needs a non-empty 'label'");
    if (!s.marks.empty() && mark.frame < s.marks.back().frame)
      throw InputError::at_line(file, line_of(&n), "marks must be in frame order");
    s.marks.push_back(mark);
  }
}

}  // namespace

u32 offset_to_address(u32 offset) { return offset < kRamBytes ? kRamBase + offset : kScratchBase + (offset - kRamBytes); }

bool address_to_offset(u32 address, u32& offset) {
  u32 phys = address & 0x1FFFFFFF;
  if (address >= kScratchBase && address < kScratchBase + kScratchBytes) {
    offset = kRamBytes + (address - kScratchBase);
    return true;
  }
  if (phys < kRamBytes && (address >> 29 == 4 || address >> 29 == 5 || address >> 29 == 0)) {
    offset = phys;
    return true;
  }
  return false;
}

long Session::snapshot_at(u64 frame) const {
  auto it = std::lower_bound(snapshot_frames.begin(), snapshot_frames.end(), frame);
  return it != snapshot_frames.end() && *it == frame ? static_cast<long>(it - snapshot_frames.begin()) : -1;
}

void write_session(const Session& s, const std::string& folder) {
  // The session is written whole into a fresh sibling folder that then takes the target's place:
  // a failed write leaves no half-written session and the old one, if any, untouched. The sibling
  // of "session/" is "session.partial", as for "session".
  namespace fs = std::filesystem;
  std::string dir = folder;
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  const std::string part = dir + ".partial";
  std::error_code ec;
  fs::remove_all(part, ec);
  fs::create_directories(part, ec);
  if (ec) throw std::runtime_error(part + ": cannot create the session folder (" + ec.message() + ")");
  psx::write_file_atomically(part + "/start.state", s.start_state);
  psx::write_file_atomically(part + "/inputs.bin", encode_inputs(s));
  psx::write_file_atomically(part + "/snapshots.bin", encode_snapshots(s));
  std::string text = manifest_text(s);
  psx::write_file_atomically(part + "/session.toml", std::vector<u8>(text.begin(), text.end()));
  if (fs::exists(dir) && !fs::exists(fs::path(dir) / "session.toml"))
    throw std::runtime_error(dir + ": exists and is not a session folder; not replaced (the new session is in " + part + ")");
  fs::remove_all(dir, ec);
  fs::rename(part, dir, ec);
  if (ec) throw std::runtime_error(dir + ": cannot move the session into place (" + ec.message() + ")");
}

Session read_session(const std::string& dir) {
  Session s;
  s.dir = dir;
  if (!std::filesystem::is_directory(dir)) throw InputError::whole(dir, "not a session folder (psxrl record makes one)");
  const std::string manifest = dir + "/session.toml";
  if (!std::filesystem::exists(manifest)) throw InputError::whole(manifest, "missing: not a session folder");
  read_manifest(manifest, s);
  s.start_state = psx::read_file(dir + "/start.state");
  decode_inputs(dir + "/inputs.bin", psx::read_file(dir + "/inputs.bin"), s);
  decode_snapshots(dir + "/snapshots.bin", psx::read_file(dir + "/snapshots.bin"), s);
  for (const Mark& m : s.marks)
    if (s.snapshot_at(m.frame) < 0)
      throw InputError::whole(dir + "/snapshots.bin", "no snapshot at mark '" + m.label + "' (frame " +
                                                          std::to_string(m.frame) + ")");
  return s;
}

}  // namespace psxrl::memsearch
