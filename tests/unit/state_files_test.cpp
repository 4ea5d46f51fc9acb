// Save-state files kept in the repository (tests/data/states/, README.md there says how they were
// made): they must keep loading in every later build, whatever changes the format or a block's
// state, through the migrations in the blocks. One is in container format 1 (psxrl's first), one
// in format 2; both are Tumble's level 1 at frame 300 of the demo script.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "cli/input_script.h"
#include "core/console.h"
#include "core/endian.h"

namespace psx {
namespace {

const std::string kDir = PSXRL_TESTDATA_DIR "/states/";
const std::string kExe = kDir + "tumble.exe";

// From tumble.elf's section headers when tumble.exe was built (README.md there): .text and
// .rodata, which the program never writes, and .text alone, where its code runs.
constexpr u32 kTextStart = 0x800103A0, kTextEnd = 0x80014CA0, kReadOnlyEnd = 0x80021450;
// Tumble's RAM contract (games/tumble/README.md): state, score, level; state 48 = playing,
// 20 = success (level complete).
constexpr u32 kState = 0x80010008, kScore = 0x8001000C, kLevel = 0x80010028;

std::vector<u8> read_all(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), {}};
}

class StateFile : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override {
    console.boot_exe(kExe);
    console.load_state_file(kDir + GetParam());
  }
  Console console;
};

TEST_P(StateFile, LoadsAtItsMomentOfTumblesLevel1) {
  EXPECT_EQ(console.frames(), 300u);
  // The program's read-only bytes in RAM are the EXE's (file offset 0x800 is load address
  // 0x80010000, psx-spx "CDROM File Formats", PS-X EXE header).
  const std::vector<u8> exe = read_all(kExe);
  ASSERT_EQ(exe.size(), 0x800u + 0x11800u);  // header + the text size in its header
  for (u32 a = kTextStart; a < kReadOnlyEnd; a += 4)
    ASSERT_EQ(console.read32(a), load_le32(&exe[0x800 + (a - 0x80010000)])) << std::hex << a;
  // A frame ends at VBlank (the GPU stops the CPU there), so the CPU is inside Tumble's code.
  const u32 pc = console.cpu().pc();
  EXPECT_TRUE(pc >= kTextStart && pc < kTextEnd) << std::hex << pc;
  // The RAM contract: magic "TMBL", level 1 in play. The demo script's moves pressed before
  // frame 286 have landed on four coins (250 each) and one fruit (500) (demo/level1.txt's
  // comments; item values in games/tumble/logic/level.h), the roll pressed at 286 has not landed.
  EXPECT_EQ(console.read32(0x80010000), 0x4C424D54u);
  EXPECT_EQ(console.read32(kLevel), 1u);
  EXPECT_EQ(console.read32(kState), 48u);
  EXPECT_EQ(console.read32(kScore), 4 * 250u + 500u);
  // Events saved by name: the video timing and the SPU's 44.1 kHz output never stop, so both are
  // always booked.
  Scheduler& s = console.scheduler();
  ASSERT_GE(s.find("gpu.video"), 0);
  ASSERT_GE(s.find("spu.sample"), 0);
  EXPECT_TRUE(s.pending(s.find("gpu.video")));
  EXPECT_TRUE(s.pending(s.find("spu.sample")));
}

TEST_P(StateFile, TheRestOfTheDemoCompletesTheLevel) {
  // The demo script from frame 300 on: its comments say the ball reaches the exit on frame 641
  // with all 4000 points and the level-complete screen lasts until frame 791.
  std::vector<psxrl::cli::InputPress> presses =
      psxrl::cli::read_input_script(PSXRL_SOURCE_DIR "/games/tumble/demo/level1.txt");
  size_t next = 0;
  for (u64 f = 0; f < 700; ++f) {
    for (; next < presses.size() && presses[next].frame == f; ++next)
      if (f >= 300) console.press_for(1, presses[next].buttons, presses[next].hold);
    if (f >= 300) console.run_frame();
  }
  EXPECT_EQ(console.read32(kState), 20u);
  EXPECT_EQ(console.read32(kScore), 4000u);
}

INSTANTIATE_TEST_SUITE_P(Formats, StateFile,
                         ::testing::Values("tumble-level1-frame300.format1.sav", "tumble-level1-frame300.format2.sav"));

// Both files hold the same moment: loaded, they give the same console.
TEST(StateFiles, Format1AndFormat2FilesGiveTheSameConsole) {
  Console a, b;
  a.boot_exe(kExe);
  b.boot_exe(kExe);
  a.load_state_file(kDir + "tumble-level1-frame300.format1.sav");
  b.load_state_file(kDir + "tumble-level1-frame300.format2.sav");
  EXPECT_EQ(a.save_state(false), b.save_state(false));
}

}  // namespace
}  // namespace psx
