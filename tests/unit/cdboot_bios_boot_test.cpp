// Tumble's disc booted as a real BIOS boots a disc: the project's cdboot ROM (tests/roms/cdboot)
// runs from reset, sets the GPU to 480-line interlace and follows the fields through GPUSTAT bits
// 31 and 13 as a BIOS shell does, then reads SYSTEM.CNF and TUMBLE.EXE through the emulated CD-ROM
// drive: no HLE, nothing side-loaded, the same calls `psxrl run --bios B --disc D` makes. Tumble
// must reach its title (state 50 in its RAM contract, games/tumble/README.md).
#include <gtest/gtest.h>

#include <string>

#include "tumble_console_util.h"

using tumble_test::Boot;
using tumble_test::TumbleConsole;

TEST(CdbootBiosBoot, TumbleDiscReachesTitleThroughTheBootRom) {
  TumbleConsole t(Boot::Disc, PSXRL_BUILD_DIR "/tests/roms/cdboot_rom.bin");
  std::string tty;
  t.console.on_tty = [&tty](char c) { tty += c; };
  for (int i = 0; i < 600 && t.state() != STATE_TITLE && !t.console.stopped(); ++i) t.console.run_frame();
  EXPECT_NE(tty.find("cdboot: GPU in 480-line interlace, fields followed"), std::string::npos) << tty;
  EXPECT_NE(tty.find("TUMBLE.EXE"), std::string::npos) << tty;
  EXPECT_EQ(t.word(TUMBLE_FIELD(magic)), TUMBLE_MAGIC);
  EXPECT_EQ(t.state(), static_cast<psx::u32>(STATE_TITLE));
  EXPECT_EQ(t.console.fatal_error(), "");
  EXPECT_FALSE(t.console.exit_code().has_value());  // the ROM stops through the exit port on errors
}
