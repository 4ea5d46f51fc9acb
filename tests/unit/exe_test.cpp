// PS-X EXE header validation: every defect names its field's offset (psx-spx "PS-X EXE" layout).
#include <gtest/gtest.h>

#include <cstring>

#include "core/bios/exe.h"
#include "core/endian.h"
#include "core/input_error.h"

namespace psx {
namespace {

std::vector<u8> make_exe(u32 pc, u32 text_addr, u32 text_size, u32 file_text_bytes) {
  std::vector<u8> f(0x800 + file_text_bytes, 0);
  std::memcpy(f.data(), "PS-X EXE", 8);
  psx::store_le32(&f[0x10], pc);
  psx::store_le32(&f[0x18], text_addr);
  psx::store_le32(&f[0x1C], text_size);
  return f;
}

std::string error_of(const std::vector<u8>& f) {
  try {
    PsxExe::parse(f, "t.exe");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PsxExe, ParsesAValidHeader) {
  auto f = make_exe(0x80010000, 0x80010000, 0x800, 0x800);
  f[0x800] = 0xAB;
  PsxExe e = PsxExe::parse(f, "t.exe");
  EXPECT_EQ(e.pc, 0x80010000u);
  EXPECT_EQ(e.text_size, 0x800u);
  ASSERT_EQ(e.text.size(), 0x800u);
  EXPECT_EQ(e.text[0], 0xAB);
}

TEST(PsxExe, RejectsEachDefectByField) {
  EXPECT_EQ(error_of(std::vector<u8>(100, 0)), "t.exe: offset 100: file ends inside the 2048-byte PS-X EXE header");
  auto bad_magic = make_exe(0x80010000, 0x80010000, 0x800, 0x800);
  bad_magic[0] = 'X';
  EXPECT_EQ(error_of(bad_magic), "t.exe: offset 0: expected the magic \"PS-X EXE\"");
  EXPECT_EQ(error_of(make_exe(0x80010000, 0x80010000, 0x700, 0x800)),
            "t.exe: offset 28: text size 1792 is not a nonzero multiple of 2048");
  // 0x801FF800 + 0x1000 runs past the end of the 2 MiB RAM.
  EXPECT_EQ(error_of(make_exe(0x80010000, 0x801FF800, 0x1000, 0x1000)),
            "t.exe: offset 24: text does not fit in RAM at its load address");
  EXPECT_EQ(error_of(make_exe(0x80010000, 0x80010000, 0x1000, 0x800)),
            "t.exe: offset 4096: file is shorter than header + text size (6144 bytes)");
  EXPECT_EQ(error_of(make_exe(0x80010002, 0x80010000, 0x800, 0x800)), "t.exe: offset 16: entry point is not word aligned");
  EXPECT_EQ(error_of(make_exe(0x1FC00000, 0x80010000, 0x800, 0x800)), "t.exe: offset 16: entry point is outside RAM");
}

}  // namespace
}  // namespace psx
