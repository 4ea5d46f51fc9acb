// Builds a bootable PlayStation data disc: an ISO 9660 volume (primary volume descriptor, set
// terminator, little- and big-endian path tables, root directory) whose logical blocks are
// written as Mode 2 Form 1 sectors with full sync, header, XA subheader, EDC and ECC. The disc
// builder tool (tools/mkdisc.cpp) and the tests use it.
#pragma once
#include <string>
#include <vector>

#include "core/disc/disc.h"

namespace psx::disc {

struct IsoFile {
  std::string name;  // ISO 9660 level 1 name in the root directory: "SYSTEM.CNF", "MAIN.EXE"
  std::vector<u8> data;
};

struct IsoOptions {
  std::string system_id = "PLAYSTATION";
  std::string volume_id = "PSXRL";
  // Text placed in system-area sector 4, where licensed discs carry the "Licensed by Sony
  // Computer Entertainment ..." line that the drive's GetID region check reads; empty = zeros.
  std::string license_text;
};

// Checks a root-directory name: 1-8 characters A-Z 0-9 _, optionally '.' and 0-3 more.
bool valid_iso_name(const std::string& name);

// The whole image as raw 2352-byte sectors, the first being logical block 0 (00:02:00).
// Throws DiscError for an invalid or duplicate file name.
std::vector<u8> build_iso(std::vector<IsoFile> files, const IsoOptions& options);

// The cue sheet for a single-track image written as `bin_file_name`.
std::string single_track_cue(const std::string& bin_file_name);

}  // namespace psx::disc
