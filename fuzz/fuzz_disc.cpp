// Fuzzes disc images and the ISO 9660 reader (src/core/disc/disc.h, iso9660.h, disc_boot.h):
// the image is opened, its sectors read, its directory tree walked and the HLE disc boot's
// SYSTEM.CNF and boot EXE lookup run. Every defect must be an InputError (DiscError), never a
// crash. The first input byte picks how the rest becomes a disc:
//   0: raw 2352-byte sectors held in memory (Disc::from_raw_sectors)
//   1: 2048-byte ISO blocks starting at logical block 16, the volume descriptor (16 zero blocks
//      are put in front, so a small input reaches the ISO 9660 parser), as Mode 2 Form 1 sectors
//   2: the bytes as an image file of unknown type (Disc::open probes raw .bin or ISO)
//   3: the bytes as a .iso file (Disc::open_iso)
#include <algorithm>
#include <cstring>
#include <memory>
#include <string>

#include "core/disc/disc.h"
#include "core/disc/disc_boot.h"
#include "core/disc/iso9660.h"
#include "core/disc/sector.h"
#include "fuzz_util.h"

using namespace psx::disc;

namespace {

// The directory tree, bounded so a directory that contains itself ends the walk.
void walk(IsoFilesystem& fs, const IsoEntry& dir, int depth, int& budget) {
  for (const IsoEntry& e : fs.list(dir)) {
    if (--budget < 0) return;
    if (e.directory) {
      if (depth < 3) walk(fs, e, depth + 1, budget);
    } else {
      fs.read(e, 16 * 1024);
    }
  }
}

std::unique_ptr<Disc> compact_iso(const std::vector<psx::u8>& blocks) {
  const psx::u32 count = 16 + static_cast<psx::u32>((blocks.size() + kDataSectorSize - 1) / kDataSectorSize);
  std::vector<psx::u8> image(size_t{count} * kRawSectorSize, 0);
  const psx::u8 subheader[4] = {0, 0, kSubmodeData, 0};
  for (psx::u32 lba = 0; lba < count; ++lba) {
    psx::u8 data[kDataSectorSize] = {};
    if (lba >= 16) {
      size_t at = size_t{lba - 16} * kDataSectorSize;
      std::memcpy(data, blocks.data() + at, std::min<size_t>(kDataSectorSize, blocks.size() - at));
    }
    build_mode2_form1(&image[size_t{lba} * kRawSectorSize], lba + kLeadInSectors, subheader, data);
  }
  return Disc::from_raw_sectors(std::move(image), "fuzz.iso");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  psxfuzz::Reader in(data, size);
  const int mode = in.byte() % 4;
  std::vector<psx::u8> bytes = in.rest();
  try {
    std::unique_ptr<Disc> disc;
    if (mode == 0) {
      disc = Disc::from_raw_sectors(std::move(bytes), "fuzz.bin");
    } else if (mode == 1) {
      disc = compact_iso(bytes);
    } else {
      auto path = psxfuzz::scratch_dir() / (mode == 2 ? "fuzz.img" : "fuzz.iso");
      psxfuzz::write_file(path, bytes.data(), bytes.size());
      disc = Disc::open(path.string());
    }
    RawSector sector;
    const psx::u32 end = std::min<psx::u32>(disc->lead_out(), kLeadInSectors + 40);
    for (psx::u32 abs = kLeadInSectors - 2; abs <= end; ++abs) {
      disc->read_sector(abs, sector);
      disc->track_at(abs);
    }
    try {
      IsoFilesystem fs(*disc);
      int budget = 64;
      walk(fs, fs.root(), 0, budget);
    } catch (const DiscError&) {
    }
    BootConfig config;
    load_boot_exe(*disc, config);
  } catch (const psx::InputError&) {
  }
  return 0;
}
