// The recompiler's code map (RecompilerT::set_code_map()): the perf-format names of the host code
// it compiles, which profilers read to attribute time to guest blocks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "core/console.h"
#include "tumble_console_util.h"

namespace {

using psx::Console;

struct Entry {
  unsigned long long start = 0;
  size_t bytes = 0;
  std::string name;
};

std::vector<Entry> parse(const std::string& map) {
  std::vector<Entry> out;
  std::istringstream in(map);
  for (std::string line; std::getline(in, line);) {
    Entry e;
    char name[40] = {};
    // perf's /tmp/perf-<pid>.map: "START SIZE symbolname", hex without a prefix.
    EXPECT_EQ(std::sscanf(line.c_str(), "%llx %zx %39s", &e.start, &e.bytes, name), 3) << line;
    e.name = name;
    out.push_back(e);
  }
  return out;
}

// Tumble booted under the recompiler, which writes its code map to `map` (null: nowhere).
void boot_tumble(Console& c, std::ostream* map) {
  c.set_cpu_mode(Console::CpuMode::Recompiler);
  c.set_code_map(map);
  c.boot_exe(TUMBLE_EXE);
}

// Tumble's title under the recompiler: one line per compiled block, the fill routines once before
// the first block that needed them, every range inside the code the recompiler holds and none
// overlapping another (the buffer only grows while nothing is dropped).
TEST(RecompilerCodeMap, NamesEveryCompiledBlockOnce) {
  Console c;
  std::ostringstream map;
  boot_tumble(c, &map);
  c.run_frames(60);
  ASSERT_EQ(c.recompiler_stats().flushes, 0u);
  const std::vector<Entry> entries = parse(map.str());
  ASSERT_FALSE(entries.empty());
  size_t blocks = 0, routines = 0, bytes = 0;
  unsigned long long end = 0;
  for (const Entry& e : entries) {
    SCOPED_TRACE(e.name);
    EXPECT_GT(e.bytes, 0u);
    EXPECT_GE(e.start, end);  // after the previous range
    end = e.start + e.bytes;
    bytes += e.bytes;
    if (e.name == "psx_fill_routines") {
      ++routines;
      continue;
    }
    ASSERT_EQ(e.name.size(), 18u);  // psx_block_ and the pc as 8 hex digits
    ASSERT_EQ(e.name.rfind("psx_block_", 0), 0u);
    EXPECT_EQ(std::stoul(e.name.substr(10), nullptr, 16) % 4, 0u);  // a pc is word-aligned
    EXPECT_EQ(e.start % 16, 0u);  // block entries are 16-byte aligned
    ++blocks;
  }
  EXPECT_EQ(blocks, c.recompiler_stats().compiled);
  EXPECT_EQ(routines, 1u);
  EXPECT_EQ(entries.front().name, "psx_fill_routines");
  EXPECT_LE(bytes, c.recompiler_code_bytes());
  // The title runs Tumble's own code, loaded at 0x80010000 (games/tumble/tumble.ld).
  EXPECT_NE(map.str().find("psx_block_8001"), std::string::npos);
}

// A map attached to a console that has run (an environment boots its game first) has what runs
// from then on compiled again and named, the fill routines too; the emulation goes on as if no
// map were attached.
TEST(RecompilerCodeMap, AttachedLateNamesWhatRunsFromThenOn) {
  Console plain, mapped;
  boot_tumble(plain, nullptr);
  boot_tumble(mapped, nullptr);
  plain.run_frames(40);
  mapped.run_frames(40);
  const auto compiled_before = mapped.recompiler_stats().compiled;
  std::ostringstream map;
  mapped.set_code_map(&map);
  plain.run_frames(20);
  mapped.run_frames(20);
  const std::vector<Entry> entries = parse(map.str());
  ASSERT_FALSE(entries.empty());
  EXPECT_EQ(entries.front().name, "psx_fill_routines");
  EXPECT_EQ(entries.size() - 1, mapped.recompiler_stats().compiled - compiled_before);
  EXPECT_TRUE(std::equal(plain.ram().begin(), plain.ram().end(), mapped.ram().begin()));
  EXPECT_EQ(plain.cycles(), mapped.cycles());
}

TEST(RecompilerCodeMap, NothingWrittenOnceUnset) {
  Console c;
  std::ostringstream map;
  c.set_code_map(&map);
  boot_tumble(c, nullptr);
  c.run_frames(10);
  EXPECT_GT(c.recompiler_stats().compiled, 0u);
  EXPECT_TRUE(map.str().empty());
}

}  // namespace
