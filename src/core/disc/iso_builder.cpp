// ISO 9660 image construction for the disc builder (ECMA-119 layout as psx-spx describes it).
// Layout: blocks 0-15 system area, 16 primary volume descriptor, 17 terminator, 18 L path table,
// 19 M path table, 20.. root directory, then each file from a fresh block in name order.
#include "core/disc/iso_builder.h"

#include <algorithm>
#include <cstring>

#include "core/endian.h"

namespace psx::disc {
namespace {

void both16(u8* p, u32 v) {
  p[0] = static_cast<u8>(v), p[1] = static_cast<u8>(v >> 8);
  p[2] = static_cast<u8>(v >> 8), p[3] = static_cast<u8>(v);
}
void be32(u8* p, u32 v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<u8>(v >> (24 - 8 * i));
}
void both32(u8* p, u32 v) { store_le32(p, v), be32(p + 4, v); }

void padded(u8* p, const std::string& s, size_t n) {
  std::memset(p, ' ', n);
  std::memcpy(p, s.data(), std::min(n, s.size()));
}

// Fixed recording date (1995-01-01 00:00:00 GMT) so that the same inputs give the same image.
constexpr u8 kRecordDate[7] = {95, 1, 1, 0, 0, 0, 0};

// Appends one directory record; returns its length.
u32 directory_record(u8* p, const std::string& name, u32 lba, u32 size, bool dir) {
  u32 name_len = static_cast<u32>(name.size());
  u32 len = 33 + name_len + (name_len % 2 == 0 ? 1 : 0);
  std::memset(p, 0, len);
  p[0] = static_cast<u8>(len);
  both32(p + 2, lba);
  both32(p + 10, size);
  std::memcpy(p + 18, kRecordDate, 7);
  p[25] = dir ? 0x02 : 0x00;
  both16(p + 28, 1);
  p[32] = static_cast<u8>(name_len);
  std::memcpy(p + 33, name.data(), name_len);
  return len;
}

void date_field(u8* p) {
  std::memcpy(p, "1995010100000000", 16);
  p[16] = 0;
}

}  // namespace

bool valid_iso_name(const std::string& name) {
  size_t dot = name.find('.');
  std::string base = name.substr(0, dot);
  std::string ext = dot == std::string::npos ? "" : name.substr(dot + 1);
  auto ok = [](const std::string& s) {
    return std::all_of(s.begin(), s.end(), [](char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'; });
  };
  return !base.empty() && base.size() <= 8 && ext.size() <= 3 && ok(base) && ok(ext);
}

std::vector<u8> build_iso(std::vector<IsoFile> files, const IsoOptions& options) {
  std::sort(files.begin(), files.end(), [](const IsoFile& a, const IsoFile& b) { return a.name < b.name; });
  for (size_t i = 0; i < files.size(); ++i) {
    if (!valid_iso_name(files[i].name))
      throw DiscError("file name '" + files[i].name + "': expected an ISO 9660 name of 1-8 characters A-Z 0-9 _ " +
                      "with an optional extension of up to 3");
    if (i && files[i].name == files[i - 1].name) throw DiscError("file name '" + files[i].name + "' given twice");
  }
  constexpr u32 kRootLba = 20;
  // Root directory: "." and ".." (34 bytes each), then one record per file (name + ";1").
  std::vector<std::vector<u8>> dir_blocks(1, std::vector<u8>(kDataSectorSize, 0));
  u32 pos = 68;
  std::vector<u32> rec_block(files.size()), rec_pos(files.size());
  for (size_t i = 0; i < files.size(); ++i) {
    u32 len = 33 + static_cast<u32>(files[i].name.size() + 2) + ((files[i].name.size() + 2) % 2 == 0 ? 1 : 0);
    if (pos + len > kDataSectorSize) dir_blocks.emplace_back(kDataSectorSize, 0), pos = 0;
    rec_block[i] = static_cast<u32>(dir_blocks.size() - 1), rec_pos[i] = pos;
    pos += len;
  }
  const u32 root_blocks = static_cast<u32>(dir_blocks.size());
  u32 next = kRootLba + root_blocks;
  std::vector<u32> file_lba(files.size());
  for (size_t i = 0; i < files.size(); ++i) {
    file_lba[i] = next;
    next += std::max<u32>(1, static_cast<u32>((files[i].data.size() + kDataSectorSize - 1) / kDataSectorSize));
  }
  const u32 total = next;
  const u32 root_size = root_blocks * kDataSectorSize;
  directory_record(dir_blocks[0].data(), std::string(1, '\0'), kRootLba, root_size, true);
  directory_record(dir_blocks[0].data() + 34, std::string(1, '\1'), kRootLba, root_size, true);
  for (size_t i = 0; i < files.size(); ++i)
    directory_record(dir_blocks[rec_block[i]].data() + rec_pos[i], files[i].name + ";1", file_lba[i],
                     static_cast<u32>(files[i].data.size()), false);

  std::vector<std::vector<u8>> blocks(total, std::vector<u8>(kDataSectorSize, 0));
  if (!options.license_text.empty())
    std::memcpy(blocks[4].data(), options.license_text.data(), std::min<size_t>(kDataSectorSize, options.license_text.size()));
  u8* pvd = blocks[16].data();
  pvd[0] = 1;
  std::memcpy(pvd + 1, "CD001", 5);
  pvd[6] = 1;
  padded(pvd + 8, options.system_id, 32);
  padded(pvd + 40, options.volume_id, 32);
  both32(pvd + 80, total);
  both16(pvd + 120, 1);
  both16(pvd + 124, 1);
  both16(pvd + 128, kDataSectorSize);
  both32(pvd + 132, 10);  // path table: the root's single 10-byte entry
  store_le32(pvd + 140, 18);
  be32(pvd + 148, 19);
  directory_record(pvd + 156, std::string(1, '\0'), kRootLba, root_size, true);
  padded(pvd + 190, "", 128);
  padded(pvd + 318, "", 128);
  padded(pvd + 446, "", 128);
  padded(pvd + 574, "PLAYSTATION", 128);
  padded(pvd + 702, "", 37 * 3);
  for (u32 off : {813u, 830u, 847u, 864u}) date_field(pvd + off);
  pvd[881] = 1;
  u8* term = blocks[17].data();
  term[0] = 0xFF;
  std::memcpy(term + 1, "CD001", 5);
  term[6] = 1;
  // Path table entry: name length 1, extent, parent directory number 1, name 00.
  blocks[18][0] = 1, store_le32(blocks[18].data() + 2, kRootLba), blocks[18][6] = 1;
  blocks[19][0] = 1, be32(blocks[19].data() + 2, kRootLba), blocks[19][7] = 1;
  for (u32 b = 0; b < root_blocks; ++b) blocks[kRootLba + b] = dir_blocks[b];
  for (size_t i = 0; i < files.size(); ++i)
    for (size_t off = 0; off < files[i].data.size(); off += kDataSectorSize)
      std::memcpy(blocks[file_lba[i] + off / kDataSectorSize].data(), files[i].data.data() + off,
                  std::min<size_t>(kDataSectorSize, files[i].data.size() - off));

  // Subheaders: data blocks; the last block of each descriptor/file/directory also carries
  // end-of-record, and the volume's last block end-of-file (as mastering tools write them).
  std::vector<u8> submode(total, kSubmodeData);
  submode[16] |= kSubmodeEor;
  submode[17] |= kSubmodeEor | kSubmodeEof;
  submode[kRootLba + root_blocks - 1] |= kSubmodeEor | kSubmodeEof;
  for (size_t i = 0; i < files.size(); ++i) {
    u32 end = (i + 1 < files.size() ? file_lba[i + 1] : total) - 1;
    submode[end] |= kSubmodeEor | kSubmodeEof;
  }
  std::vector<u8> image(static_cast<size_t>(total) * kRawSectorSize);
  for (u32 b = 0; b < total; ++b) {
    u8 sub[4] = {0, 0, submode[b], 0};
    build_mode2_form1(image.data() + static_cast<size_t>(b) * kRawSectorSize, b + kLeadInSectors, sub, blocks[b].data());
  }
  return image;
}

std::string single_track_cue(const std::string& bin_file_name) {
  return "FILE \"" + bin_file_name + "\" BINARY\n  TRACK 01 MODE2/2352\n    INDEX 01 00:00:00\n";
}

}  // namespace psx::disc
