// HLE kernel: the "cdrom:" device and the CD-ROM calls of table A0h (psx-spx "BIOS CDROM
// Functions"): files found through the disc's ISO 9660 directories (disc/iso9660.h) and read in
// whole 800h-byte sectors, CdGetLbn/CdReadSector/CdGetStatus, the asynchronous CdAsyncSeekL/
// GetStatus/ReadSector/SetMode, and the CD driver's set-up calls.
// The sectors come straight from the disc image, not through the CD-ROM controller: a read
// completes at once and leaves the controller's registers and the drive's head as they were.
#include <algorithm>
#include <cstring>

#include "core/bios/hle_bios.h"
#include "core/bios/hle_costs.h"
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
constexpr u32 kRawAfterSync = 0x924, kRawAfterSubheader = 0x918;
// The asynchronous calls' completion events (psx-spx "Event Summary", F0000003h CDROM hardware):
// 20h = command complete, 8000h = error (here: no disc).
constexpr u32 kCdEvent = 0xF0000003, kCdDone = 0x0020, kCdError = 0x8000;
constexpr u32 kModeSize924 = 0x20, kModeSize918 = 0x10;  // Setmode bits 5 and 4
u32 bcd(u8 v) { return (v >> 4) * 10 + (v & 0x0F); }

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

// Appends `count` logical blocks from `lba` to out, `size` bytes of each as the drive delivers
// them (psx-spx "CDROM Controller Command Summary", Setmode bits 4-5): 800h = the user data of a
// Mode 1 or Mode 2 Form 1 sector, 924h = all but the 12 sync bytes, 918h = all after the header
// and subheader.
bool HleBios::cd_sectors(u32 lba, u32 count, u32 size, std::vector<u8>& out) {
  disc::Disc* d = disc_in_drive ? disc_in_drive() : nullptr;
  if (!d) return false;
  disc::RawSector raw;
  for (u32 i = 0; i < count; ++i) {
    if (!d->read_sector(lba + i + disc::kLeadInSectors, raw)) return false;
    u32 from = size == kRawAfterSync ? 0x0C : size == kRawAfterSubheader ? 0x18
               : raw[15] == 1 ? disc::kMode1DataOffset : disc::kMode2DataOffset;
    out.insert(out.end(), raw.begin() + from, raw.begin() + from + size);
  }
  return true;
}

// Copies the 800h user-data bytes of `count` logical blocks to RAM.
bool HleBios::cd_read_blocks(u32 lba, u32 count, u32 dst) {
  return cd_to_ram(lba, count, kSector, dst);
}

// Sectors to RAM; the BIOS moves them by DMA, which reaches only RAM (and its mirrors).
bool HleBios::cd_to_ram(u32 lba, u32 count, u32 size, u32 dst) {
  std::vector<u8> data;
  if (Bus::physical(dst) >= 0x00800000 || count > Bus::kRamSize / size || !cd_sectors(lba, count, size, data))
    return false;
  for (u32 k = 0; k < data.size(); ++k) bus_.ram()[Bus::physical(dst + k) & (Bus::kRamSize - 1)] = data[k];
  const u32 p = Bus::physical(dst) & (Bus::kRamSize - 1);
  bus_.host_wrote_ram(p, std::min<u32>(static_cast<u32>(data.size()), Bus::kRamSize - p));
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
    case 0x78:
    case 0x7C:
    case 0x7E:
    case 0x81: return cd_async_call(fn);
    // _96_init and its subfunction: the CD file system starts at the root directory again.
    case 0x54:
    case 0x71:
    case 0x95: io_.cd_dir.fill(0); return_to_caller(0); return true;
    // _96_remove, EnqueueCdIntr/DequeueCdIntr, SetCdromIrqAutoAbort: no BIOS CD-ROM interrupt
    // handler exists here to add or remove, so CD-ROM IRQs stay the program's own; _96_remove
    // takes a BIOS's time.
    case 0x56:
    case 0x72: return_after(0, hle_cost::kCdRemove); return true;
    case 0x9E:
    case 0xA2:
    case 0xA3: return_to_caller(0); return true;
    default: return false;
  }
}

// CdAsyncSeekL/GetStatus/ReadSector/SetMode (psx-spx "BIOS CDROM Functions"): the command's
// effect at once, its completion event (F0000003h: 20h, or 8000h with no disc) delivered before
// the call returns 1.
bool HleBios::cd_async_call(u32 fn) {
  const u32 a0 = cpu_.reg(kRegA0), a1 = cpu_.reg(kRegA1), a2 = cpu_.reg(kRegA2);
  bool ok = disc_in_drive && disc_in_drive();
  switch (fn) {
    case 0x78:  // CdAsyncSeekL(src): MM, SS, FF in BCD; logical block = (MM*60+SS)*75+FF - 150
      io2_.cd_seek_lba = (bcd(peek8(a0)) * 60 + bcd(peek8(a0 + 1))) * 75 + bcd(peek8(a0 + 2)) - 150;
      break;
    case 0x7C:  // CdAsyncGetStatus(dst): the status byte
      poke8(a0, static_cast<u8>(ok ? kStatMotorOn : kStatShellOpen));
      ok = true;
      break;
    case 0x7E: {  // CdAsyncReadSector(count, dst, mode): mode bits 0-7 are the Setmode byte
      io2_.cd_mode = a2 & 0xFF;
      const u32 size = (a2 & kModeSize918) ? kRawAfterSubheader : (a2 & kModeSize924) ? kRawAfterSync : kSector;
      ok = ok && cd_to_ram(io2_.cd_seek_lba, a0, size, a1);
      if (ok) io2_.cd_seek_lba += a0;
      break;
    }
    default: io2_.cd_mode = a0 & 0xFF; break;  // CdAsyncSetMode(mode)
  }
  deliver_event(kCdEvent, ok ? kCdDone : kCdError);
  return_after_events(1);
  return true;
}

}  // namespace psx
