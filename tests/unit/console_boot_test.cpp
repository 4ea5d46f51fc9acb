// Console boot paths with a BIOS: booting a disc starts the BIOS afresh, without side-loading an
// EXE left from an earlier boot_exe(); the project's cdboot ROM boots a mkdisc disc through the
// Console API as `psxrl run --bios --disc` does.
#include <gtest/gtest.h>

#include <string>

#include "core/console.h"

namespace psx {
namespace {

const std::string kRoms = PSXRL_BUILD_DIR "/tests/roms/";

std::string run_and_capture(Console& c, u64 frames) {
  std::string out;
  c.on_tty = [&out](char ch) { out += ch; };
  c.run_frames(frames);
  c.on_tty = nullptr;
  return out;
}

TEST(ConsoleBoot, DiscBootDropsAnEarlierEXE) {
  // bootrom.bin jumps to the shell entry, where a pending EXE would be side-loaded.
  Console c;
  c.load_bios(kRoms + "bootrom.bin");
  c.boot_exe(kRoms + "hello.exe");
  c.insert_disc(kRoms + "cdrom_test.cue");
  c.boot_disc();
  std::string out = run_and_capture(c, 5);
  EXPECT_NE(out.find("psxrl boot ROM"), std::string::npos);
  EXPECT_EQ(out.find("hello from the PlayStation"), std::string::npos) << out;
  EXPECT_FALSE(c.exit_code().has_value());
}

TEST(ConsoleBoot, CdbootRomBootsAMkdiscDisc) {
  Console c;
  c.load_bios(kRoms + "cdboot_rom.bin");
  c.insert_disc(kRoms + "cdboot_test.cue");
  c.boot_disc();
  std::string out = run_and_capture(c, 600);
  ASSERT_TRUE(c.exit_code().has_value()) << out;
  EXPECT_EQ(*c.exit_code(), 0u) << out;  // the disc's program exits with its failure count
  EXPECT_NE(out.find("booted by the cdboot ROM"), std::string::npos) << out;
}

}  // namespace
}  // namespace psx
