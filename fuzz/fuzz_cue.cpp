// Fuzzes cue sheets (src/core/disc/cue.h): the text parser, then Disc::open_cue laying the
// tracks out over image files and reading the sectors. Image files are a few fixed files in a
// scratch folder; sheets naming anything outside it (a path with a separator) are only parsed,
// so the fuzzer never opens the host's own files (a FIFO there would block the run).
#include <string>

#include "core/disc/cue.h"
#include "core/disc/disc.h"
#include "core/disc/sector.h"
#include "fuzz_util.h"

using namespace psx::disc;

namespace {

// Images the sheets may name: raw 2352-byte sectors, 2048-byte blocks, a size that is neither,
// and an empty file.
const std::filesystem::path& image_dir() {
  static const std::filesystem::path dir = [] {
    const auto& d = psxfuzz::scratch_dir();
    std::vector<psx::u8> raw(4 * kRawSectorSize);
    const psx::u8 subheader[4] = {0, 0, kSubmodeData, 0};
    psx::u8 block[kDataSectorSize] = {'C', 'D'};
    for (psx::u32 i = 0; i < 4; ++i) build_mode2_form1(&raw[i * kRawSectorSize], kLeadInSectors + i, subheader, block);
    psxfuzz::write_file(d / "a.bin", raw.data(), raw.size());
    psxfuzz::write_file(d / "b.iso", raw.data(), 3 * kDataSectorSize);
    psxfuzz::write_file(d / "c.bin", raw.data(), 1000);
    psxfuzz::write_file(d / "e.bin", raw.data(), 0);
    return d;
  }();
  return dir;
}

bool local_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." && name.find_first_of("/\\") == std::string::npos;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    CueSheet sheet = parse_cue(text, "fuzz.cue");
    for (const CueFile& f : sheet.files) {
      if (!local_name(f.name)) return 0;
      for (const CueTrack& t : f.tracks)
        if (t.indexes.empty()) __builtin_trap();  // parse_cue promises INDEX 01 in every track
    }
    const auto path = image_dir() / "fuzz.cue";
    psxfuzz::write_file(path, data, size);
    auto disc = Disc::open_cue(path.string());
    RawSector sector;
    // Every track boundary and a few sectors around it; the lead-out must not be readable.
    for (const Track& t : disc->tracks())
      for (psx::u32 abs : {t.index0, t.index1, t.end - 1, t.end}) {
        disc->read_sector(abs, sector);
        disc->track_at(abs);
      }
    if (disc->read_sector(disc->lead_out(), sector)) __builtin_trap();
  } catch (const psx::InputError&) {
  }
  return 0;
}
