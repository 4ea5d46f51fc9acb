// Disc image model and the readers for ISO (2048-byte sectors) and lone raw .bin images. Sectors
// are fetched from the image file when the drive asks for them; nothing is loaded whole.
#include "core/disc/disc.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace psx::disc {
namespace {

std::string lower_extension(const std::string& path) {
  size_t dot = path.find_last_of('.');
  size_t slash = path.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

constexpr u8 kDataSubheader[4] = {0, 0, kSubmodeData, 0};

}  // namespace

Disc::~Disc() {
  for (Source& s : sources_)
    if (s.file) std::fclose(s.file);
}

int Disc::add_file_source(const std::string& file_path, u64& size_out) {
  // fopen opens a folder and seeking to its end gives LLONG_MAX: refuse it by name.
  if (std::error_code ec; std::filesystem::is_directory(file_path, ec))
    throw DiscError(file_path + ": is a folder, expected an image file");
  std::FILE* f = std::fopen(file_path.c_str(), "rb");
  if (!f) throw DiscError(file_path + ": cannot open image file (" + std::strerror(errno) + ")");
  if (fseeko(f, 0, SEEK_END) != 0) {
    std::fclose(f);
    throw DiscError(file_path + ": cannot determine the file size");
  }
  size_out = static_cast<u64>(ftello(f));
  Source s;
  s.name = file_path;
  s.file = f;
  sources_.push_back(std::move(s));
  return static_cast<int>(sources_.size() - 1);
}

std::unique_ptr<Disc> Disc::open(const std::string& path) {
  if (std::error_code ec; std::filesystem::is_directory(path, ec))
    throw DiscError(path + ": is a folder, expected a disc image (.cue, .bin or .iso)");
  std::string ext = lower_extension(path);
  if (ext == "cue") return open_cue(path);
  if (ext == "iso") return open_iso(path);
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw DiscError(path + ": cannot open disc image (" + std::strerror(errno) + ")");
  u8 head[16] = {};
  size_t got = std::fread(head, 1, sizeof head, f);
  u8 cd001[5] = {};
  bool iso = fseeko(f, 16 * kDataSectorSize + 1, SEEK_SET) == 0 && std::fread(cd001, 1, 5, f) == 5 &&
             std::memcmp(cd001, "CD001", 5) == 0;
  std::fclose(f);
  if (got == sizeof head && has_sync(head)) return open_bin(path);
  if (iso) return open_iso(path);
  throw DiscError(path + ": offset 0: not a disc image (expected the CD sync pattern 00 FF..FF 00 of a raw "
                  "2352-byte image, or an ISO 9660 volume descriptor at offset 32768)");
}

std::unique_ptr<Disc> Disc::open_iso(const std::string& path) {
  auto disc = std::make_unique<Disc>(path);
  u64 size = 0;
  int src = disc->add_file_source(path, size);
  if (size == 0) throw DiscError(path + ": the image is empty");
  if (size % kDataSectorSize != 0)
    throw DiscError(path + ": size " + std::to_string(size) + " is not a multiple of 2048 bytes (truncated image?)");
  u32 count = static_cast<u32>(size / kDataSectorSize);
  disc->add_extent({kLeadInSectors, count, src, 0, kDataSectorSize, TrackType::Mode2});
  disc->add_track({1, TrackType::Mode2, 0, kLeadInSectors, kLeadInSectors + count});
  disc->set_lead_out(kLeadInSectors + count);
  return disc;
}

std::unique_ptr<Disc> Disc::open_bin(const std::string& path) {
  auto disc = std::make_unique<Disc>(path);
  u64 size = 0;
  int src = disc->add_file_source(path, size);
  if (size == 0 || size % kRawSectorSize != 0)
    throw DiscError(path + ": size " + std::to_string(size) +
                    " is not a nonzero multiple of 2352 bytes (truncated raw image?)");
  RawSector first;
  if (!disc->read_source(disc->sources_[src], 0, first.data(), kRawSectorSize)) throw DiscError(disc->last_error_);
  if (first[15] != 1 && first[15] != 2)
    throw DiscError(path + ": offset 15: sector mode byte is " + std::to_string(first[15]) + ", expected 1 or 2");
  TrackType type = first[15] == 1 ? TrackType::Mode1 : TrackType::Mode2;
  u32 count = static_cast<u32>(size / kRawSectorSize);
  disc->add_extent({kLeadInSectors, count, src, 0, kRawSectorSize, type});
  disc->add_track({1, type, 0, kLeadInSectors, kLeadInSectors + count});
  disc->set_lead_out(kLeadInSectors + count);
  return disc;
}

std::unique_ptr<Disc> Disc::from_raw_sectors(std::vector<u8> image, std::string name) {
  auto disc = std::make_unique<Disc>(name);
  u32 count = static_cast<u32>(image.size() / kRawSectorSize);
  Source s;
  s.name = std::move(name);
  s.memory = std::move(image);
  disc->sources_.push_back(std::move(s));
  disc->add_extent({kLeadInSectors, count, 0, 0, kRawSectorSize, TrackType::Mode2});
  disc->add_track({1, TrackType::Mode2, 0, kLeadInSectors, kLeadInSectors + count});
  disc->set_lead_out(kLeadInSectors + count);
  return disc;
}

const Track* Disc::track_at(u32 abs) const {
  for (const Track& t : tracks_)
    if (abs >= t.index0 && abs < t.end) return &t;
  return nullptr;
}

bool Disc::read_source(const Source& src, u64 offset, u8* dst, u32 n) {
  if (!src.file) {
    if (offset + n > src.memory.size()) return false;
    std::memcpy(dst, src.memory.data() + offset, n);
    return true;
  }
  if (fseeko(src.file, static_cast<off_t>(offset), SEEK_SET) != 0 || std::fread(dst, 1, n, src.file) != n) {
    last_error_ = src.name + ": offset " + std::to_string(offset) + ": read failed (file shorter than the image?)";
    return false;
  }
  return true;
}

void Disc::synthesise(const Extent* e, u32 abs, RawSector& out) const {
  out.fill(0);
  const Track* t = track_at(abs);
  TrackType type = e ? e->type : (t ? t->type : TrackType::Mode2);
  if (type == TrackType::Audio) return;
  if (type == TrackType::Mode1) {
    write_sync_header(out.data(), abs, 1);
    finish_mode1(out.data());
    return;
  }
  // An empty Form 2 sector, as mastering tools write in data-track pregaps.
  write_sync_header(out.data(), abs, 2);
  out[18] = out[22] = kSubmodeForm2;
  finish_mode2_form2(out.data());
}

bool Disc::read_sector(u32 abs, RawSector& out) {
  if (abs >= lead_out_) return false;
  auto it = std::find_if(extents_.begin(), extents_.end(),
                         [abs](const Extent& e) { return abs >= e.start && abs < e.start + e.count; });
  if (it == extents_.end() || it->source < 0) {
    synthesise(it == extents_.end() ? nullptr : &*it, abs, out);
    return true;
  }
  u64 offset = it->offset + static_cast<u64>(abs - it->start) * it->sector_size;
  if (it->sector_size == kRawSectorSize) return read_source(sources_[it->source], offset, out.data(), kRawSectorSize);
  out.fill(0);
  if (it->type == TrackType::Mode1) {
    if (!read_source(sources_[it->source], offset, out.data() + kMode1DataOffset, kDataSectorSize)) return false;
    write_sync_header(out.data(), abs, 1);
    finish_mode1(out.data());
    return true;
  }
  u8 data[kDataSectorSize];
  if (!read_source(sources_[it->source], offset, data, kDataSectorSize)) return false;
  build_mode2_form1(out.data(), abs, kDataSubheader, data);
  return true;
}

}  // namespace psx::disc
