// Fuzzes the memory search's user input (src/memsearch/): marks files, query text, and session
// folders whose snapshot file is the fuzz input. Each is either accepted or refused with
// psx::InputError / QueryError; nothing else may escape and nothing may crash.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "core/input_error.h"
#include "memsearch/marks.h"
#include "memsearch/search.h"
#include "memsearch/session.h"

namespace ms = psxrl::memsearch;

namespace {

// A small valid session to run queries on and to take a snapshot file's place in.
const ms::Session& base_session() {
  static const ms::Session s = [] {
    ms::Session b;
    b.frames = 3;
    b.snapshot_interval = 1;
    b.pad1.assign(3, 0);
    b.pad2.assign(3, 0);
    b.marks = {{1, "coin"}, {2, "turn"}};
    for (psx::u64 f = 0; f < 3; ++f) {
      b.snapshot_frames.push_back(f);
      b.snapshots.emplace_back(ms::kSnapshotBytes, static_cast<psx::u8>(f));
    }
    return b;
  }();
  return s;
}

void fuzz_session_file(const std::string& bytes) {
  static const std::string dir = [] {
    std::string d = (std::filesystem::temp_directory_path() / ("psxrl_fuzz_session_" + std::to_string(getpid()))).string();
    ms::write_session(base_session(), d);
    return d;
  }();
  std::ofstream(dir + "/snapshots.bin", std::ios::binary | std::ios::trunc).write(bytes.data(), bytes.size());
  try {
    ms::Session s = ms::read_session(dir);
    if (s.snapshots.size() != s.snapshot_frames.size()) __builtin_trap();
    for (const auto& snap : s.snapshots)
      if (snap.size() != ms::kSnapshotBytes) __builtin_trap();
  } catch (const psx::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  switch (data[0] % 3) {
    case 0:
      try {
        ms::parse_marks(text, "fuzz.marks");
      } catch (const psx::InputError&) {
      }
      break;
    case 1: {
      // 4 KiB of RAM and the scratchpad's start: every query path, at a size fuzzing can afford.
      ms::Search search(base_session(), {ms::Encoding::U8, ms::Encoding::S16BE, ms::Encoding::BCD32},
                        ms::kRamBytes - 4096, ms::kRamBytes + 64);
      try {
        search.apply(text);
        search.ranked(5);
      } catch (const ms::QueryError&) {
      }
      break;
    }
    default:
      fuzz_session_file(text);
  }
  return 0;
}
