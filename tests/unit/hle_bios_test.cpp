// HLE kernel save states: the kernel's interrupt dispatch, events, pad and heap state all go
// through do_state, so saving anywhere in a program that lives on kernel interrupt chains, events
// and callbacks (tests/roms/bios_interrupts.c) and loading into a fresh console gives the same
// result as not saving; the same for the file functions' handles, the asynchronous CD calls'
// position and a qsort/lsearch/bsearch under way.
#include <gtest/gtest.h>

#include "core/console.h"
#include "core/hash.h"

namespace psx {
namespace {

const std::string kProgram = PSXRL_BUILD_DIR "/tests/roms/bios_interrupts.exe";

struct Outcome {
  std::optional<u32> exit_code;
  u64 ram_hash;
  Cycles cycles;
  bool operator==(const Outcome&) const = default;
};

Outcome finish(Console& c) {
  for (int i = 0; i < 2000 && !c.stopped(); ++i) c.run_cycles(20011);
  return {c.exit_code(), fnv1a(c.ram().data(), c.ram().size()), c.cycles()};
}

TEST(HleBiosState, SaveAnywhereLoadInFreshConsoleSameOutcome) {
  Console ref;
  ref.boot_exe(kProgram);
  Outcome expected = finish(ref);
  ASSERT_EQ(expected.exit_code, std::optional<u32>(0)) << ref.fatal_error();

  // Odd, prime-spaced save points land inside kernel calls, chain walks and callbacks.
  Console a;
  a.boot_exe(kProgram);
  for (int point = 0; point < 40 && !a.stopped(); ++point) {
    a.run_cycles(104729 + 7919 * point);
    if (a.stopped()) break;  // the exit port's stop is not machine state
    std::vector<u8> blob = a.save_state();
    Console b;
    b.boot_exe(kProgram);
    b.load_state(blob);
    Outcome got = finish(b);
    EXPECT_EQ(got.exit_code, expected.exit_code) << "save point " << point << ": " << b.fatal_error();
    EXPECT_EQ(got.ram_hash, expected.ram_hash) << "save point " << point;
  }
}

// The file functions' handles and positions are kernel state too: saving inside
// tests/roms/bios_files.c (cdrom: files open, seeks, TTY handles closed and reopened) and loading
// into a fresh console with the same disc ends as the uninterrupted run.
TEST(HleBiosState, FileHandlesSurviveSaveAndLoad) {
  const std::string program = PSXRL_BUILD_DIR "/tests/roms/bios_files.exe";
  const std::string disc = PSXRL_BUILD_DIR "/tests/roms/cdrom_test.cue";
  auto boot = [&](Console& c) {
    c.insert_disc(disc);
    c.boot_exe(program);
  };
  Console ref;
  boot(ref);
  Outcome expected = finish(ref);
  ASSERT_EQ(expected.exit_code, std::optional<u32>(0)) << ref.fatal_error();
  for (int point = 0; point < 12; ++point) {
    Console a;
    boot(a);
    a.run_cycles(1009 + 79999 * point);  // the program runs about 900,000 cycles
    if (a.stopped()) break;
    std::vector<u8> blob = a.save_state();
    Console b;
    boot(b);
    b.load_state(blob);
    Outcome got = finish(b);
    EXPECT_EQ(got.exit_code, expected.exit_code) << "save point " << point << ": " << b.fatal_error();
    EXPECT_EQ(got.ram_hash, expected.ram_hash) << "save point " << point;
  }
}

// The asynchronous CD calls' sector and mode (HLEK version 5) are kernel state: saving anywhere
// in tests/roms/bios_misc.c (between CdAsyncSeekL and the reads that continue from it) and loading
// into a fresh console ends as the uninterrupted run.
TEST(HleBiosState, AsyncCdPositionSurvivesSaveAndLoad) {
  const std::string program = PSXRL_BUILD_DIR "/tests/roms/bios_misc.exe";
  const std::string disc = PSXRL_BUILD_DIR "/tests/roms/cdrom_test.cue";
  auto boot = [&](Console& c) {
    c.insert_disc(disc);
    c.boot_exe(program);
  };
  Console ref;
  boot(ref);
  Outcome expected = finish(ref);
  ASSERT_EQ(expected.exit_code, std::optional<u32>(0)) << ref.fatal_error();
  for (Cycles point = 997; point < expected.cycles; point += expected.cycles / 16) {
    Console a;
    boot(a);
    a.run_cycles(point);
    if (a.stopped()) break;
    std::vector<u8> blob = a.save_state();
    Console b;
    boot(b);
    b.load_state(blob);
    Outcome got = finish(b);
    EXPECT_EQ(got.exit_code, expected.exit_code) << "save at cycle " << point << ": " << b.fatal_error();
  }
}

// A qsort/lsearch/bsearch under way (HLEK version 6) is kernel state: the comparisons return to
// the kernel, which resumes the search. Saving anywhere in tests/roms/bios_stdlib.c (mostly inside
// its 200-key sort, whose comparisons are slow) and loading into a fresh console ends as the
// uninterrupted run, with the same RAM.
TEST(HleBiosState, SearchUnderWaySurvivesSaveAndLoad) {
  const std::string program = PSXRL_BUILD_DIR "/tests/roms/bios_stdlib.exe";
  Console ref;
  ref.boot_exe(program);
  Outcome expected = finish(ref);
  ASSERT_EQ(expected.exit_code, std::optional<u32>(0)) << ref.fatal_error();
  for (Cycles point = 1009; point < expected.cycles; point += expected.cycles / 16) {
    Console a;
    a.boot_exe(program);
    a.run_cycles(point);
    if (a.stopped()) break;
    std::vector<u8> blob = a.save_state();
    Console b;
    b.boot_exe(program);
    b.load_state(blob);
    Outcome got = finish(b);
    EXPECT_EQ(got.exit_code, expected.exit_code) << "save at cycle " << point << ": " << b.fatal_error();
    EXPECT_EQ(got.ram_hash, expected.ram_hash) << "save at cycle " << point;
  }
}

}  // namespace
}  // namespace psx
