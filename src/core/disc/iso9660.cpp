// ISO 9660 reader: volume descriptor and directory record parsing (psx-spx "CDROM ISO ...").
#include "core/disc/iso9660.h"

#include <algorithm>
#include <cstring>

#include "core/endian.h"

namespace psx::disc {
namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string strip_version(std::string name) {
  size_t semi = name.find(';');
  if (semi != std::string::npos) name.erase(semi);
  // "NAME." (a file without extension) is recorded with a trailing dot.
  if (!name.empty() && name.back() == '.') name.pop_back();
  return name;
}

std::string trim_right(const u8* p, size_t n) {
  std::string s(reinterpret_cast<const char*>(p), n);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\0')) s.pop_back();
  return s;
}

// A directory record: length, extent (both-endian at 2), size (both-endian at 10), flags at 25,
// name length at 32, name at 33.
IsoEntry parse_record(const u8* r) {
  IsoEntry e;
  e.lba = load_le32(r + 2);
  e.size = load_le32(r + 10);
  e.directory = (r[25] & 0x02) != 0;
  e.name = strip_version(std::string(reinterpret_cast<const char*>(r + 33), r[32]));
  return e;
}

}  // namespace

IsoFilesystem::IsoFilesystem(Disc& disc) : disc_(disc) {
  u8 pvd[kDataSectorSize];
  read_block(16, pvd);
  if (pvd[0] != 1 || std::memcmp(pvd + 1, "CD001", 5) != 0)
    throw DiscError(disc.path() + ": logical block 16: no ISO 9660 primary volume descriptor (expected type 1 'CD001')");
  if (pvd[156] < 34)
    throw DiscError(disc.path() + ": logical block 16, byte 156: root directory record is " + std::to_string(pvd[156]) +
                    " bytes, expected at least 34");
  root_ = parse_record(pvd + 156);
  root_.directory = true;
  root_.name.clear();
  volume_id_ = trim_right(pvd + 40, 32);
}

void IsoFilesystem::read_block(u32 lba, u8* out) {
  RawSector raw;
  if (!disc_.read_sector(lba + kLeadInSectors, raw))
    throw DiscError(disc_.path() + ": logical block " + std::to_string(lba) + ": cannot read sector" +
                    (disc_.last_error().empty() ? "" : " (" + disc_.last_error() + ")"));
  std::memcpy(out, raw.data() + (raw[15] == 1 ? kMode1DataOffset : kMode2DataOffset), kDataSectorSize);
}

std::vector<IsoEntry> IsoFilesystem::list(const IsoEntry& dir) {
  std::vector<IsoEntry> out;
  u32 blocks = (dir.size + kDataSectorSize - 1) / kDataSectorSize;
  if (blocks > 4096) throw DiscError(disc_.path() + ": directory at block " + std::to_string(dir.lba) + " is implausibly large");
  u8 block[kDataSectorSize];
  for (u32 b = 0; b < blocks; ++b) {
    read_block(dir.lba + b, block);
    // Records never cross a block boundary; a zero length byte pads to the next block.
    for (u32 pos = 0; pos < kDataSectorSize && block[pos] != 0;) {
      u32 len = block[pos];
      if (len < 34 || pos + len > kDataSectorSize || 33u + block[pos + 32] > len)
        throw DiscError(disc_.path() + ": logical block " + std::to_string(dir.lba + b) + " offset " +
                        std::to_string(pos) + ": malformed directory record");
      u8 name0 = block[pos + 33];
      if (!(block[pos + 32] == 1 && (name0 == 0 || name0 == 1))) out.push_back(parse_record(block + pos));
      pos += len;
    }
  }
  return out;
}

std::optional<IsoEntry> IsoFilesystem::find(const std::string& path) {
  std::string p = path;
  if (upper(p.substr(0, 6)) == "CDROM:") p.erase(0, 6);
  IsoEntry cur = root_;
  size_t i = 0;
  while (i < p.size()) {
    size_t j = p.find_first_of("\\/", i);
    if (j == std::string::npos) j = p.size();
    std::string part = upper(strip_version(p.substr(i, j - i)));
    i = j + 1;
    if (part.empty()) continue;
    if (!cur.directory) return std::nullopt;
    bool found = false;
    for (const IsoEntry& e : list(cur)) {
      if (upper(e.name) == part) {
        cur = e;
        found = true;
        break;
      }
    }
    if (!found) return std::nullopt;
  }
  return cur;
}

std::vector<u8> IsoFilesystem::read(const IsoEntry& file, u32 max_size) {
  if (file.size > max_size)
    throw DiscError(disc_.path() + ": file '" + file.name + "' is " + std::to_string(file.size) +
                    " bytes, more than the " + std::to_string(max_size) + " expected");
  std::vector<u8> out(file.size);
  u8 block[kDataSectorSize];
  for (u32 done = 0, b = 0; done < file.size; ++b) {
    read_block(file.lba + b, block);
    u32 n = std::min<u32>(kDataSectorSize, file.size - done);
    std::memcpy(out.data() + done, block, n);
    done += n;
  }
  return out;
}

}  // namespace psx::disc
