// CUE sheet parsing: the text format that describes how BIN files make up a disc (FILE, TRACK,
// INDEX, PREGAP, POSTGAP; REM/TITLE/... are ignored). The parse is pure text -> CueSheet so that
// every defect can be reported with the sheet's name and line number; Disc::open_cue then lays
// the tracks out on the disc and checks them against the image files.
#pragma once
#include <string>
#include <vector>

#include "core/disc/disc.h"

namespace psx::disc {

struct CueIndex {
  u32 number = 0;
  u32 frame = 0;  // position in the file, in sectors
  int line = 0;
};

struct CueTrack {
  u32 number = 0;
  TrackType type = TrackType::Mode2;
  u32 sector_size = kRawSectorSize;
  u32 pregap = 0;  // sectors not stored in the file, before the track
  u32 postgap = 0;
  std::vector<CueIndex> indexes;  // increasing numbers; INDEX 01 always present after parsing
  int line = 0;

  const CueIndex& first_index() const { return indexes.front(); }
  u32 index1_frame() const;
};

struct CueFile {
  std::string name;  // as written in the sheet (relative to the sheet's folder unless absolute)
  int line = 0;
  std::vector<CueTrack> tracks;
};

struct CueSheet {
  std::vector<CueFile> files;
};

// Throws DiscError("<sheet>:<line>: <what was expected>") on any malformed or unsupported line.
CueSheet parse_cue(const std::string& text, const std::string& sheet_name);

}  // namespace psx::disc
