// A disc image as the drive sees it: tracks (audio or data) laid out on one timeline of absolute
// sectors (MSF 00:00:00 = 0), each sector 2352 raw bytes, read on demand from the image files.
// Opens CUE/BIN sheets (cue.h), ISO images of 2048-byte sectors, and lone .bin files recognised
// by the data sync pattern. Pregaps not stored in the image are synthesised.
#pragma once
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/disc/sector.h"
#include "core/input_error.h"
#include "core/types.h"

namespace psx::disc {

// A defect in a user's disc image or cue sheet; the message names the file, the line or offset,
// and what was expected. An InputError, so front ends report it like any bad user file.
class DiscError : public InputError {
 public:
  using InputError::InputError;
};

enum class TrackType : u8 { Audio, Mode1, Mode2 };

struct Track {
  u8 number = 1;
  TrackType type = TrackType::Mode2;
  u32 index0 = 0;  // absolute sector where the track's pregap starts (INDEX 00 or PREGAP)
  u32 index1 = 0;  // absolute sector of INDEX 01, the track's start in the TOC
  u32 end = 0;     // one past the track's last sector
};

class Disc {
 public:
  // Where a run of consecutive sectors comes from: an image file (or memory buffer) at a byte
  // offset with 2352- or 2048-byte sectors, or nothing (a synthesised pregap).
  struct Extent {
    u32 start = 0;   // absolute sector
    u32 count = 0;
    int source = -1;  // index into the sources, -1 = synthesised
    u64 offset = 0;   // byte offset of the first sector in the source
    u32 sector_size = kRawSectorSize;
    TrackType type = TrackType::Mode2;
  };

  ~Disc();
  Disc(const Disc&) = delete;
  Disc& operator=(const Disc&) = delete;

  // Opens by extension: .cue, .iso; anything else is probed (sync pattern = raw 2352 image,
  // otherwise an ISO if the size is a multiple of 2048 and a volume descriptor is found).
  static std::unique_ptr<Disc> open(const std::string& path);
  static std::unique_ptr<Disc> open_cue(const std::string& path);
  static std::unique_ptr<Disc> open_iso(const std::string& path);
  static std::unique_ptr<Disc> open_bin(const std::string& path);
  // A single data track held in memory (raw 2352-byte sectors from 00:02:00); for tests and tools.
  static std::unique_ptr<Disc> from_raw_sectors(std::vector<u8> image, std::string name = "memory");

  const std::string& path() const { return path_; }
  const std::vector<Track>& tracks() const { return tracks_; }
  u32 lead_out() const { return lead_out_; }
  // The track holding absolute sector `abs` (its pregap included); nullptr in the lead-in/out.
  const Track* track_at(u32 abs) const;

  // Reads the raw sector at `abs`. Sectors of a 2048-byte image are returned as Mode 2 Form 1
  // sectors with a data subheader and valid EDC/ECC; pregaps read as silence (audio) or empty
  // Mode 2 sectors (data). Returns false beyond the lead-out or when the image file fails.
  bool read_sector(u32 abs, RawSector& out);
  // The last read failure (file and offset), for the log.
  const std::string& last_error() const { return last_error_; }

  // Assembly, used by the readers in disc.cpp and cue.cpp.
  Disc(std::string path) : path_(std::move(path)) {}
  int add_file_source(const std::string& file_path, u64& size_out);
  void add_extent(const Extent& e) { extents_.push_back(e); }
  void add_track(const Track& t) { tracks_.push_back(t); }
  void set_lead_out(u32 abs) { lead_out_ = abs; }

 private:
  struct Source {
    std::string name;
    std::FILE* file = nullptr;
    std::vector<u8> memory;
  };
  bool read_source(const Source& src, u64 offset, u8* dst, u32 n);
  void synthesise(const Extent* e, u32 abs, RawSector& out) const;

  std::string path_;
  std::vector<Source> sources_;
  std::vector<Extent> extents_;
  std::vector<Track> tracks_;
  u32 lead_out_ = 0;
  std::string last_error_;
};

}  // namespace psx::disc
