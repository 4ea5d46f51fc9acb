// CUE sheet parser and the CUE/BIN disc layout (tracks, indexes, pregaps) on the absolute-sector
// timeline: the first track's INDEX 01 sits at 00:02:00, after the 2-second lead-in pregap.
#include "core/disc/cue.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace psx::disc {
namespace {

class LineError {
 public:
  LineError(const std::string& sheet, int line) : where_(sheet + ":" + std::to_string(line) + ": ") {}
  [[noreturn]] void operator()(const std::string& what) const { throw DiscError(where_ + what); }

 private:
  std::string where_;
};

// Splits a line into words; "double quoted" words may contain spaces.
std::vector<std::string> tokenize(const std::string& line, const LineError& fail) {
  std::vector<std::string> out;
  size_t i = 0;
  while (i < line.size()) {
    if (std::isspace(static_cast<unsigned char>(line[i]))) {
      ++i;
      continue;
    }
    if (line[i] == '"') {
      size_t close = line.find('"', i + 1);
      if (close == std::string::npos) fail("unterminated quoted name (expected a closing \")");
      out.push_back(line.substr(i + 1, close - i - 1));
      i = close + 1;
      continue;
    }
    size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

u32 parse_number(const std::string& s, u32 max, const char* what, const LineError& fail) {
  if (s.empty() || s.size() > 3 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
    fail(std::string("expected ") + what + ", found '" + s + "'");
  u32 v = static_cast<u32>(std::stoul(s));
  if (v > max) fail(std::string(what) + " " + s + " is out of range (at most " + std::to_string(max) + ")");
  return v;
}

// mm:ss:ff with ss < 60 and ff < 75, in sectors.
u32 parse_msf(const std::string& s, const LineError& fail) {
  unsigned m, sec, f;
  char tail;
  if (std::sscanf(s.c_str(), "%u:%u:%u%c", &m, &sec, &f, &tail) != 3)
    fail("expected a time mm:ss:ff, found '" + s + "'");
  if (sec >= 60 || f >= kSectorsPerSecond || m > 99)
    fail("time '" + s + "' out of range (seconds must be below 60, frames below 75)");
  return (m * 60 + sec) * kSectorsPerSecond + f;
}

void parse_track_mode(CueTrack& t, const std::string& mode, const LineError& fail) {
  std::string m = upper(mode);
  if (m == "AUDIO") t.type = TrackType::Audio, t.sector_size = kRawSectorSize;
  else if (m == "MODE1/2352") t.type = TrackType::Mode1, t.sector_size = kRawSectorSize;
  else if (m == "MODE2/2352") t.type = TrackType::Mode2, t.sector_size = kRawSectorSize;
  else if (m == "MODE1/2048") t.type = TrackType::Mode1, t.sector_size = kDataSectorSize;
  else if (m == "MODE2/2048") t.type = TrackType::Mode2, t.sector_size = kDataSectorSize;
  else fail("unsupported track mode '" + mode + "' (expected AUDIO, MODE1/2352, MODE2/2352, MODE1/2048 or MODE2/2048)");
}

void finish_track(const CueTrack* t, const std::string& sheet) {
  if (!t) return;
  if (std::none_of(t->indexes.begin(), t->indexes.end(), [](const CueIndex& i) { return i.number == 1; }))
    LineError(sheet, t->line)("TRACK " + std::to_string(t->number) + " has no INDEX 01");
}

}  // namespace

u32 CueTrack::index1_frame() const {
  for (const CueIndex& i : indexes)
    if (i.number == 1) return i.frame;
  return indexes.front().frame;
}

CueSheet parse_cue(const std::string& text, const std::string& sheet_name) {
  CueSheet sheet;
  CueTrack* track = nullptr;
  std::istringstream in(text);
  std::string raw;
  int line_no = 0;
  u32 last_track_number = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    LineError fail(sheet_name, line_no);
    if (line_no == 1 && raw.size() >= 3 && raw.compare(0, 3, "\xEF\xBB\xBF") == 0) raw.erase(0, 3);
    std::vector<std::string> w = tokenize(raw, fail);
    if (w.empty()) continue;
    std::string cmd = upper(w[0]);
    if (cmd == "REM" || cmd == "CATALOG" || cmd == "CDTEXTFILE" || cmd == "TITLE" || cmd == "PERFORMER" ||
        cmd == "SONGWRITER" || cmd == "FLAGS" || cmd == "ISRC")
      continue;
    if (cmd == "FILE") {
      if (w.size() < 3) fail("expected FILE \"name\" BINARY");
      std::string type = upper(w.back());
      if (type != "BINARY") fail("unsupported file type '" + w.back() + "' (only BINARY images are supported)");
      finish_track(track, sheet_name);
      track = nullptr;
      std::string name = w[1];
      for (size_t i = 2; i + 1 < w.size(); ++i) name += " " + w[i];  // an unquoted name with spaces
      sheet.files.push_back({name, line_no, {}});
    } else if (cmd == "TRACK") {
      if (sheet.files.empty()) fail("TRACK before any FILE");
      if (w.size() != 3) fail("expected TRACK nn MODE");
      finish_track(track, sheet_name);
      CueTrack t;
      t.number = parse_number(w[1], 99, "a track number 1-99", fail);
      if (t.number == 0) fail("track number 0 is not allowed (tracks are numbered 1-99)");
      if (last_track_number && t.number != last_track_number + 1)
        fail("TRACK " + w[1] + " out of order (expected track " + std::to_string(last_track_number + 1) + ")");
      last_track_number = t.number;
      t.line = line_no;
      parse_track_mode(t, w[2], fail);
      auto& tracks = sheet.files.back().tracks;
      if (!tracks.empty() && tracks.front().sector_size != t.sector_size)
        fail("tracks of different sector sizes in one FILE are not supported");
      tracks.push_back(t);
      track = &tracks.back();
    } else if (cmd == "INDEX") {
      if (!track) fail("INDEX before any TRACK");
      if (w.size() != 3) fail("expected INDEX nn mm:ss:ff");
      CueIndex idx{parse_number(w[1], 99, "an index number 0-99", fail), parse_msf(w[2], fail), line_no};
      if (!track->indexes.empty() && idx.number <= track->indexes.back().number)
        fail("INDEX " + w[1] + " out of order (index numbers must increase within a track)");
      if (!track->indexes.empty() && idx.frame < track->indexes.back().frame)
        fail("INDEX " + w[1] + " at " + w[2] + " lies before the previous index");
      if (track->indexes.empty() && idx.number > 1) fail("INDEX " + w[1] + " before INDEX 01");
      track->indexes.push_back(idx);
    } else if (cmd == "PREGAP" || cmd == "POSTGAP") {
      if (!track) fail(cmd + " before any TRACK");
      if (w.size() != 2) fail("expected " + cmd + " mm:ss:ff");
      if (cmd == "PREGAP" && !track->indexes.empty()) fail("PREGAP must come before the track's INDEX lines");
      (cmd == "PREGAP" ? track->pregap : track->postgap) = parse_msf(w[1], fail);
    } else {
      fail("unknown command '" + w[0] + "' (expected FILE, TRACK, INDEX, PREGAP, POSTGAP or REM)");
    }
  }
  finish_track(track, sheet_name);
  for (const CueFile& f : sheet.files)
    if (f.tracks.empty()) LineError(sheet_name, f.line)("FILE '" + f.name + "' has no TRACK");
  if (sheet.files.empty()) LineError(sheet_name, line_no)("no FILE/TRACK found (expected at least one track)");
  return sheet;
}

namespace {

std::string resolve(const std::filesystem::path& dir, const std::string& name) {
  namespace fs = std::filesystem;
  fs::path p(name);
  if (p.is_absolute()) return name;
  fs::path full = dir / p;
  std::error_code ec;
  if (fs::exists(full, ec)) return full.string();
  // Sheets written on case-insensitive file systems often differ from the file's real case.
  std::string want = upper(p.filename().string());
  for (const auto& e : fs::directory_iterator(full.parent_path().empty() ? "." : full.parent_path(), ec))
    if (upper(e.path().filename().string()) == want) return e.path().string();
  return full.string();
}

}  // namespace

std::unique_ptr<Disc> Disc::open_cue(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw DiscError(path + ": cannot open cue sheet (" + std::strerror(errno) + ")");
  std::string text;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0 && text.size() < (1u << 20)) text.append(buf, n);
  std::fclose(f);
  CueSheet sheet = parse_cue(text, path);

  auto disc = std::make_unique<Disc>(path);
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  u32 cursor = kLeadInSectors;
  bool first_track = true;
  for (const CueFile& file : sheet.files) {
    LineError file_fail(path, file.line);
    std::string file_path = resolve(dir, file.name);
    u64 size = 0;
    int src;
    try {
      src = disc->add_file_source(file_path, size);
    } catch (const DiscError& e) {
      file_fail(e.what());
    }
    u32 ss = file.tracks.front().sector_size;
    if (size % ss != 0)
      file_fail("size " + std::to_string(size) + " of '" + file_path + "' is not a multiple of the " +
                std::to_string(ss) + "-byte sector size of its tracks (truncated image?)");
    u32 file_sectors = static_cast<u32>(size / ss);
    for (size_t k = 0; k < file.tracks.size(); ++k) {
      const CueTrack& t = file.tracks[k];
      LineError track_fail(path, t.line);
      u32 first = t.first_index().frame;
      u32 next = k + 1 < file.tracks.size() ? file.tracks[k + 1].first_index().frame : file_sectors;
      u32 idx1 = t.index1_frame();
      if (idx1 >= next || first >= file_sectors)
        track_fail("TRACK " + std::to_string(t.number) + " starts beyond the end of '" + file_path + "' (" +
                   std::to_string(file_sectors) + " sectors; truncated image?)");
      u32 in_file_gap = idx1 - first;
      Track out{static_cast<u8>(t.number), t.type, cursor, 0, 0};
      if (first_track) {
        if (in_file_gap + t.pregap > kLeadInSectors)
          track_fail("the first track's pregap is longer than the 2-second lead-in");
        cursor = kLeadInSectors - in_file_gap;
        out.index0 = 0;
        first_track = false;
      } else if (t.pregap) {
        disc->add_extent({cursor, t.pregap, -1, 0, ss, t.type});
        cursor += t.pregap;
      }
      disc->add_extent({cursor, next - first, src, static_cast<u64>(first) * ss, ss, t.type});
      out.index1 = cursor + in_file_gap;
      cursor += next - first;
      if (t.postgap) {
        disc->add_extent({cursor, t.postgap, -1, 0, ss, t.type});
        cursor += t.postgap;
      }
      out.end = cursor;
      disc->add_track(out);
    }
  }
  disc->set_lead_out(cursor);
  return disc;
}

}  // namespace psx::disc
