// HLE kernel: the "cdrom:" device and the CD-ROM calls of table A0h (psx-spx "BIOS CDROM
// Functions"): files found through the disc's ISO 9660 directories (disc/iso9660.h) and read in
// whole 800h-byte sectors, CdGetLbn/CdReadSector/CdGetStatus, and the CD driver's set-up calls.
// The sectors come straight from the disc image, not through the CD-ROM controller: a read
// completes at once and leaves the controller's registers and the drive's head as they were.
#include <cstring>

#include "core/bios/hle_bios.h"
#include "core/bus.h"
#include "core/disc/iso9660.h"

namespace psx {

namespace {
constexpr u32 kRegA0 = 4, kRegA1 = 5, kRegA2 = 6;
constexpr u32 kFail = 0xFFFFFFFF;
constexpr u32 kSector = disc::kDataSectorSize;
// CdGetStatus's status byte (psx-spx "CDROM Controller Command Summary", stat): motor on, or
// the shell open when the drive is empty.
constexpr u32 kStatMotorOn = 0x02, kStatShellOpen = 0x10;

// "cdrom:FILE" names the part after the device; a path may use '/' as well as '\'.
std::string without_device(const std::string& s) {
  size_t colon = s.find(':');
  std::string p = colon == std::string::npos ? s : s.substr(colon + 1);
  for (char& c : p)
    if (c == '/') c = '\\';
  return p;
}
}  // namespace

// A path relative to cd()'s directory unless it starts at the root.
std::string HleBios::cd_full_path(const std::string& path) const {
  std::string p = without_device(path);
  if (!p.empty() && p[0] == '\\') return p;
  std::string dir;
  for (char c : io_.cd_dir) {
    if (!c) break;
    dir += c == '/' ? '\\' : c;
  }
  if (dir.empty() || dir[0] != '\\') dir = "\\" + dir;
  if (dir.back() != '\\') dir += '\\';
  return dir + p;
}

u32 HleBios::cd_open(const std::string& path, HleFile& f) {
  disc::Disc* d = disc_in_drive ? disc_in_drive() : nullptr;
  if (!d) return kEIo;
  try {
    disc::IsoFilesystem fs(*d);
    auto e = fs.find(cd_full_path(path));
    if (!e || e->directory) return kENoEnt;
    f.first = e->lba;
    f.size = e->size;
    return 0;
  } catch (const disc::DiscError&) {
    return kEIo;
  }
}

// read(fd, dst, len) on cdrom: len and the file pointer must be whole sectors and the pointer
// inside the file; whole sectors are written to dst, and the count returned stops at the file's
// end (psx-spx "read": "per $0800 from cdrom"; error 16h otherwise).
u32 HleBios::cd_read(HleFile& f, u32 dst, u32 len) {
  if ((len % kSector) || (f.pos % kSector) || f.pos >= f.size || static_cast<s32>(len) < 0)
    return file_fail(&f, kEInval);
  if (!cd_read_blocks(f.first + f.pos / kSector, len / kSector, dst)) return file_fail(&f, kEIo);
  u32 n = std::min(len, f.size - f.pos);
  f.pos += n;
  return n;
}

// Copies the 800h user-data bytes of `count` logical blocks (Mode 1 or Mode 2 Form 1) to RAM.
bool HleBios::cd_read_blocks(u32 lba, u32 count, u32 dst) {
  disc::Disc* d = disc_in_drive ? disc_in_drive() : nullptr;
  if (!d) return false;
  disc::RawSector raw;
  for (u32 i = 0; i < count; ++i) {
    if (!d->read_sector(lba + i + disc::kLeadInSectors, raw)) return false;
    const u8* data = raw.data() + (raw[15] == 1 ? disc::kMode1DataOffset : disc::kMode2DataOffset);
    // The BIOS moves sectors by DMA, which reaches only RAM (and its mirrors).
    const u32 at = dst + i * kSector;
    if (Bus::physical(at) >= 0x00800000) return false;
    for (u32 k = 0; k < kSector; ++k) bus_.ram()[Bus::physical(at + k) & (Bus::kRamSize - 1)] = data[k];
    bus_.host_wrote_ram(Bus::physical(at) & (Bus::kRamSize - 1), kSector);
  }
  return true;
}

// A directory's files for firstfile2/nextfile: names with their ";1" version, attribute 0, the
// first logical block as the sector (psx-spx "firstfile2": "always 0 for cdrom").
std::vector<HleBios::DirEntry> HleBios::cd_entries(const std::string& dir) {
  std::vector<DirEntry> out;
  disc::Disc* d = disc_in_drive ? disc_in_drive() : nullptr;
  if (!d) return out;
  try {
    disc::IsoFilesystem fs(*d);
    std::optional<disc::IsoEntry> at = dir.empty() || dir == "\\" ? fs.root() : fs.find(dir);
    if (!at || !at->directory) return out;
    for (const disc::IsoEntry& e : fs.list(*at)) out.push_back({e.directory ? e.name : e.name + ";1", 0, e.size, e.lba});
  } catch (const disc::DiscError&) {
    out.clear();
  }
  return out;
}

bool HleBios::cd_call(u32 fn) {
  const u32 a0 = cpu_.reg(kRegA0), a1 = cpu_.reg(kRegA1), a2 = cpu_.reg(kRegA2);
  switch (fn) {
    case 0xA4: {  // CdGetLbn(filename): the file's first logical block, -1 when there is none
      HleFile f;
      return_to_caller(cd_open(read_string(a0), f) ? kFail : f.first);
      return true;
    }
    case 0xA5:  // CdReadSector(count, sector, buffer): count, or -1
      return_to_caller(cd_read_blocks(a1, a0, a2) ? a0 : kFail);
      return true;
    case 0xA6: {  // CdGetStatus
      bool disc = disc_in_drive && disc_in_drive();
      return_to_caller(disc ? kStatMotorOn : kStatShellOpen);
      return true;
    }
    // _96_init and its subfunction: the CD file system starts at the root directory again.
    case 0x54:
    case 0x71:
    case 0x95: io_.cd_dir.fill(0); return_to_caller(0); return true;
    // _96_remove, EnqueueCdIntr/DequeueCdIntr, SetCdromIrqAutoAbort: no BIOS CD-ROM interrupt
    // handler exists here to add or remove, so CD-ROM IRQs stay the program's own.
    case 0x56:
    case 0x72:
    case 0x9E:
    case 0xA2:
    case 0xA3: return_to_caller(0); return true;
    default: return false;
  }
}

}  // namespace psx
