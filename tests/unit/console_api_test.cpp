// Console calls not covered elsewhere (src/core/console.h): boot_exe_image, boot_bios, run_until
// and dump_ram, on tiny programs assembled here so every expected value follows from the code.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/console.h"
#include "core/endian.h"

namespace psx {
namespace {

// MIPS I encodings (psx-spx "CPU Opcode Encoding").
constexpr u32 lui(u32 rt, u32 imm) { return 0x3C000000 | rt << 16 | imm; }
constexpr u32 ori(u32 rt, u32 rs, u32 imm) { return 0x34000000 | rs << 21 | rt << 16 | imm; }
constexpr u32 sh(u32 rt, u32 base, u32 off) { return 0xA4000000 | base << 21 | rt << 16 | off; }
constexpr u32 jr(u32 rs) { return rs << 21 | 0x08; }
constexpr u32 j(u32 addr) { return 0x08000000 | ((addr >> 2) & 0x03FFFFFF); }
constexpr u32 kT0 = 8, kT1 = 9;

constexpr u32 kText = 0x80010000;

// A PS-X EXE (psx-spx "CDROM File Formats"): 2048-byte header, text padded to 2048 bytes; BSS of
// 16 bytes at 0x80020000, stack at 0x801FFF00.
std::vector<u8> make_exe(const std::vector<u32>& code) {
  std::vector<u8> f(0x800 + 0x800, 0);
  std::memcpy(f.data(), "PS-X EXE", 8);
  store_le32(&f[0x10], kText);       // pc
  store_le32(&f[0x14], 0x80018000);  // gp
  store_le32(&f[0x18], kText);       // text address
  store_le32(&f[0x1C], 0x800);       // text size
  store_le32(&f[0x28], 0x80020000);  // BSS
  store_le32(&f[0x2C], 16);
  store_le32(&f[0x30], 0x801FFF00);  // stack base
  for (size_t i = 0; i < code.size(); ++i) store_le32(&f[0x800 + 4 * i], code[i]);
  return f;
}

// Writes 42 to the debug exit port 0x1F802082 (DESIGN.md "Debug ports"), then loops.
std::vector<u8> exit42_exe() {
  return make_exe({lui(kT0, 0x1F80), ori(kT1, 0, 42), sh(kT1, kT0, 0x2082), j(kText + 12), 0});
}
// Loops forever at its entry.
std::vector<u8> loop_exe() { return make_exe({j(kText), 0}); }

TEST(ConsoleApi, BootExeImageLoadsTextClearsBssAndSetsRegisters) {
  Console c;
  c.write32(0x80020004, 0xDEADBEEF);  // inside the BSS: the loader must clear it
  const std::vector<u8> exe = exit42_exe();
  c.boot_exe_image(exe, "exit42.exe");
  for (u32 i = 0; i < 0x800; i += 4) ASSERT_EQ(c.read32(kText + i), load_le32(&exe[0x800 + i])) << i;
  EXPECT_EQ(c.read32(0x80020004), 0u);
  // The HLE kernel hands over after its boot delay (a kernel loop that ends with `jr k0`, so the
  // program starts at the frame phase a BIOS's Exec() gives it: hle_costs.h kBootCycles).
  EXPECT_EQ(c.cpu().reg(26), kText);        // k0: where the boot delay jumps
  EXPECT_EQ(c.cpu().reg(28), 0x80018000u);  // gp from the header
  EXPECT_EQ(c.cpu().reg(29), 0x801FFF00u);  // sp = stack base + offset 0
  c.run_frame();
  ASSERT_TRUE(c.stopped());
  EXPECT_EQ(c.exit_code(), 42u);
}

TEST(ConsoleApi, BootExeImageRefusesADefectiveImageNamingIt) {
  Console c;
  std::vector<u8> exe = loop_exe();
  store_le32(&exe[0x1C], 0x700);  // not a multiple of 2048
  try {
    c.boot_exe_image(exe, "odd.exe");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("odd.exe"), std::string::npos) << m;
    EXPECT_NE(m.find("text size 1792 is not a nonzero multiple of 2048"), std::string::npos) << m;
  }
}

// A 512 KiB BIOS whose reset code (0xBFC00000, psx-spx "Memory Map") jumps to the shell entry
// 0x80030000, where boot_exe side-loads a pending EXE as the BIOS's Exec() would.
std::vector<u8> shell_bios() {
  std::vector<u8> bios(Bus::kBiosSize, 0);
  const u32 code[] = {lui(kT0, 0x8003), jr(kT0), 0};
  for (size_t i = 0; i < std::size(code); ++i) store_le32(&bios[4 * i], code[i]);
  return bios;
}

TEST(ConsoleApi, BootExeImageWithBiosSideLoadsAtTheShellEntry) {
  Console c;
  c.load_bios_image(shell_bios(), "shell.bin");
  c.boot_exe_image(exit42_exe(), "exit42.exe");
  EXPECT_EQ(c.cpu().pc(), 0xBFC00000u);  // the BIOS runs first, from the reset vector
  EXPECT_EQ(c.read32(kText), 0u);         // the EXE is not in RAM yet
  c.run_frame();
  ASSERT_TRUE(c.stopped());
  EXPECT_EQ(c.exit_code(), 42u);
}

TEST(ConsoleApi, BootBiosStartsFromResetAndDropsAPendingExe) {
  Console c;
  c.load_bios_image(shell_bios(), "shell.bin");
  c.boot_exe_image(exit42_exe(), "exit42.exe");
  c.boot_bios();
  EXPECT_EQ(c.cpu().pc(), 0xBFC00000u);
  // At the shell entry nothing is side-loaded: RAM there is zero (nop), the CPU runs on, the
  // program never writes its exit code.
  c.run_frames(2);
  EXPECT_FALSE(c.stopped());
  EXPECT_EQ(c.read32(kText), 0u);
}

TEST(ConsoleApi, RunUntilChecksBeforeEachFrameAndStopsAtTheBound) {
  Console c;
  c.boot_exe_image(loop_exe(), "loop.exe");
  // Already true: no frame runs.
  EXPECT_TRUE(c.run_until([] { return true; }, 10));
  EXPECT_EQ(c.frames(), 0u);
  // True after the fifth frame: exactly five run.
  EXPECT_TRUE(c.run_until([&c] { return c.frames() >= 5; }, 100));
  EXPECT_EQ(c.frames(), 5u);
  // Never true: the bound is the number of frames run.
  EXPECT_FALSE(c.run_until([] { return false; }, 7));
  EXPECT_EQ(c.frames(), 12u);
}

TEST(ConsoleApi, RunUntilReturnsWhenTheProgramStops) {
  Console c;
  c.boot_exe_image(exit42_exe(), "exit42.exe");
  EXPECT_FALSE(c.run_until([] { return false; }, 1000));
  EXPECT_EQ(c.exit_code(), 42u);
  // The exit is written in the first frame's first instructions; no further frame ran.
  EXPECT_EQ(c.frames(), 0u);
}

TEST(ConsoleApi, DumpRamWritesTheWhole2MiB) {
  Console c;
  const std::vector<u8> exe = exit42_exe();
  c.boot_exe_image(exe, "exit42.exe");
  const std::filesystem::path p =
      std::filesystem::path(::testing::TempDir()) / ("psxrl_ram_" + std::to_string(::getpid()) + ".bin");
  c.dump_ram(p.string());
  std::ifstream f(p, std::ios::binary);
  const std::vector<u8> ram{std::istreambuf_iterator<char>(f), {}};
  std::filesystem::remove(p);
  ASSERT_EQ(ram.size(), 2u * 1024 * 1024);
  // RAM offset 0x10000 is 0x80010000 (KSEG0 maps physical 0): the EXE's text.
  EXPECT_TRUE(std::equal(exe.begin() + 0x800, exe.end(), ram.begin() + 0x10000));
  EXPECT_THROW(c.dump_ram((p.parent_path() / "missing" / "ram.bin").string()), std::runtime_error);
}

}  // namespace
}  // namespace psx
