// ISO 9660 lookup on an image the test builds, the image's descriptor bytes at the offsets
// ECMA-119/psx-spx document, and the SYSTEM.CNF boot configuration the HLE disc boot reads.
#include <gtest/gtest.h>

#include <cstring>

#include "core/disc/disc_boot.h"
#include "core/disc/iso9660.h"
#include "core/disc/iso_builder.h"

namespace psx::disc {
namespace {

std::vector<u8> text(const std::string& s) { return {s.begin(), s.end()}; }

std::vector<u8> fake_exe(u32 size, u8 fill) {
  std::vector<u8> e(size, fill);
  std::memset(e.data(), 0, 0x800);
  std::memcpy(e.data(), "PS-X EXE", 8);
  return e;
}

const u8* block(const std::vector<u8>& image, u32 lba) { return image.data() + lba * kRawSectorSize + kMode2DataOffset; }
u32 le32(const u8* p) { return p[0] | p[1] << 8 | p[2] << 16 | static_cast<u32>(p[3]) << 24; }
u32 be32(const u8* p) { return static_cast<u32>(p[0]) << 24 | p[1] << 16 | p[2] << 8 | p[3]; }

TEST(DiscIso9660, BuiltImageHasDocumentedDescriptors) {
  std::vector<u8> img = build_iso({{"SYSTEM.CNF", text("BOOT = cdrom:\\MAIN.EXE;1\r\n")}, {"MAIN.EXE", fake_exe(5000, 1)}},
                                  IsoOptions{"PLAYSTATION", "TESTVOL", ""});
  // 20 (descriptors, path tables) + 1 root block + MAIN.EXE (3 blocks) + SYSTEM.CNF (1 block).
  ASSERT_EQ(img.size(), 25u * kRawSectorSize);
  const u8* pvd = block(img, 16);
  EXPECT_EQ(pvd[0], 1);
  EXPECT_EQ(0, std::memcmp(pvd + 1, "CD001", 5));
  EXPECT_EQ(0, std::memcmp(pvd + 8, "PLAYSTATION ", 12));
  EXPECT_EQ(0, std::memcmp(pvd + 40, "TESTVOL ", 8));
  EXPECT_EQ(le32(pvd + 80), 25u);
  EXPECT_EQ(be32(pvd + 84), 25u);
  EXPECT_EQ(pvd[128] | pvd[129] << 8, 2048);
  EXPECT_EQ(le32(pvd + 156 + 2), 20u);  // root directory extent
  EXPECT_EQ(block(img, 17)[0], 0xFF);   // set terminator
  EXPECT_EQ(le32(block(img, 18) + 2), 20u);  // L path table: root at block 20
  EXPECT_EQ(be32(block(img, 19) + 2), 20u);  // M path table, big-endian
  // Every sector is Mode 2 at its own address.
  for (u32 b = 0; b < 25; ++b) {
    const u8* raw = img.data() + b * kRawSectorSize;
    ASSERT_TRUE(has_sync(raw));
    u32 abs = (from_bcd(raw[12]) * 60 + from_bcd(raw[13])) * 75 + from_bcd(raw[14]);
    ASSERT_EQ(abs, b + 150);
  }
}

TEST(DiscIso9660, LookupFindsFilesCaseInsensitively) {
  std::vector<u8> big(70000);
  for (size_t i = 0; i < big.size(); ++i) big[i] = static_cast<u8>(i * 7);
  auto disc = Disc::from_raw_sectors(build_iso({{"LEVEL1.DAT", big}, {"README", text("hi")}}, IsoOptions{}));
  IsoFilesystem fs(*disc);
  EXPECT_EQ(fs.volume_id(), "PSXRL");
  auto e = fs.find("cdrom:\\level1.dat;1");
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->size, 70000u);
  EXPECT_EQ(fs.read(*e, 1 << 20), big);
  ASSERT_TRUE(fs.find("/README").has_value());
  EXPECT_FALSE(fs.find("cdrom:\\MISSING.EXE;1").has_value());
  EXPECT_FALSE(fs.find("README\\X").has_value());
  EXPECT_EQ(fs.list(fs.root()).size(), 2u);
  EXPECT_THROW(fs.read(*e, 1000), DiscError);
}

TEST(DiscIso9660, NotAnIsoVolume) {
  std::vector<u8> img(20 * kRawSectorSize, 0);
  auto disc = Disc::from_raw_sectors(img, "blank.bin");
  try {
    IsoFilesystem fs(*disc);
    FAIL() << "no error";
  } catch (const DiscError& e) {
    EXPECT_NE(std::string(e.what()).find("blank.bin: logical block 16"), std::string::npos) << e.what();
  }
}

TEST(DiscIso9660, SystemCnfSettings) {
  BootConfig c = parse_system_cnf("BOOT = cdrom:\\SLUS_123.45;1 arg\r\nTCB = 8\r\nEVENT = 20\r\nSTACK = 801FFFF0\r\n", "S");
  EXPECT_EQ(c.boot_path, "cdrom:\\SLUS_123.45;1");
  EXPECT_EQ(c.boot_argument, "arg");
  EXPECT_EQ(c.tcb, 8u);
  EXPECT_EQ(c.event, 0x20u);
  EXPECT_EQ(c.stack, 0x801FFFF0u);
  BootConfig d = parse_system_cnf("BOOT=cdrom:GAME.EXE\n", "S");  // documented defaults otherwise
  EXPECT_EQ(d.tcb, 4u);
  EXPECT_EQ(d.event, 0x10u);
  EXPECT_EQ(d.stack, 0x801FFF00u);
  try {
    parse_system_cnf("BOOT = cdrom:\\A.EXE;1\nSTACK = 80zz\n", "disc.cue:SYSTEM.CNF");
    FAIL() << "no error";
  } catch (const DiscError& e) {
    EXPECT_NE(std::string(e.what()).find("disc.cue:SYSTEM.CNF:2: expected a hexadecimal number"), std::string::npos);
  }
}

TEST(DiscIso9660, BootConfigFromDisc) {
  auto disc = Disc::from_raw_sectors(build_iso(
      {{"SYSTEM.CNF", text("BOOT = cdrom:\\MAIN.EXE;1\r\nSTACK = 801FFFF0\r\n")}, {"MAIN.EXE", fake_exe(4096, 9)}}, {}));
  BootConfig c = read_boot_config(*disc);
  EXPECT_EQ(c.stack, 0x801FFFF0u);
  ASSERT_EQ(c.exe.size(), 4096u);
  EXPECT_EQ(c.exe[0x900], 9);
  // Without SYSTEM.CNF the BIOS boots cdrom:\PSX.EXE;1.
  auto plain = Disc::from_raw_sectors(build_iso({{"PSX.EXE", fake_exe(2048, 3)}}, {}));
  EXPECT_EQ(read_boot_config(*plain).exe.size(), 2048u);
  auto broken = Disc::from_raw_sectors(build_iso({{"SYSTEM.CNF", text("BOOT = cdrom:\\NONE.EXE;1\n")}}, {}), "x.bin");
  EXPECT_THROW(read_boot_config(*broken), DiscError);
  EXPECT_THROW(build_iso({{"bad name.exe", {}}}, {}), DiscError);
}

}  // namespace
}  // namespace psx::disc
