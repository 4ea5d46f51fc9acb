// Fuzzes save states (psx::Console::load_state, src/core/save_state.h): a state either loads or
// is refused with StateError, leaving the console as it was, and a console that loaded one keeps
// running (whatever it holds is guest behaviour). A whole payload is megabytes of RAM and VRAM,
// too big to mutate usefully, so most inputs are edits to a real state:
//   byte 0 even: the rest is the state file itself (container: magic, version, hashes, sizes,
//                checksum, zlib)
//   byte 0 odd:  edits to a real payload, each {anchor u8, offset u16, length u8 (1-16), bytes}:
//                the anchor picks a block's section tag (found by scanning the payload, so new
//                blocks need no change here); with bit 1 set the first edit's position instead
//                cuts the payload short. The result is packed with valid hashes and checksum.
#include <vector>

#include "core/console.h"
#include "core/save_state.h"
#include "fuzz_util.h"

namespace {

// The program every console here runs: `j 0x80010000; nop`, an endless loop.
const std::vector<psx::u8>& program() {
  static const std::vector<psx::u8> exe = psxfuzz::make_exe({0x00, 0x40, 0x00, 0x08, 0, 0, 0, 0});
  return exe;
}

struct Base {
  std::vector<psx::u8> payload;
  std::vector<size_t> anchors;  // offsets of section headers: 4 tag characters, small version
  psx::SaveStateHeader header;
};

const Base& base() {
  static const Base b = [] {
    Base b;
    psx::Console c;
    c.boot_exe_image(program(), "fuzz.exe");
    c.run_frames(2);
    std::vector<psx::u8> file = c.save_state(false);
    b.payload.assign(file.begin() + psx::SaveStateHeader::kSize, file.end());
    b.header.bios_hash = 0;
    for (int i = 0; i < 8; ++i) b.header.program_hash |= psx::u64(file[24 + i]) << (8 * i);
    auto tag_char = [](psx::u8 c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == ' '; };
    const auto& p = b.payload;
    for (size_t i = 0; i + 8 <= p.size(); ++i)
      if (tag_char(p[i]) && tag_char(p[i + 1]) && tag_char(p[i + 2]) && tag_char(p[i + 3]) && p[i] != ' ' &&
          p[i + 4] >= 1 && p[i + 4] < 16 && !p[i + 5] && !p[i + 6] && !p[i + 7])
        b.anchors.push_back(i);
    if (b.anchors.size() < 10) __builtin_trap();  // the scan no longer finds the blocks
    return b;
  }();
  return b;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, size_t size) {
  const Base& b = base();
  psxfuzz::Reader in(data, size);
  const psx::u8 mode = in.byte();
  std::vector<psx::u8> file;
  if (mode & 1) {
    std::vector<psx::u8> p = b.payload;
    bool cut = mode & 2;
    while (!in.empty()) {
      size_t at = b.anchors[in.byte() % b.anchors.size()];
      at += in.u16();
      if (cut) {
        p.resize(std::min(at, p.size()));
        cut = false;
        continue;
      }
      for (int n = in.byte() % 16 + 1; n > 0; --n, ++at) {
        const psx::u8 v = in.byte();
        if (at < p.size()) p[at] = v;
      }
    }
    file = psx::pack_save_state(b.header, p);
  } else {
    file = in.rest();
  }
  psx::Console console;
  console.boot_exe_image(program(), "fuzz.exe");
  try {
    console.load_state(file);
  } catch (const psx::StateError&) {
    return 0;
  }
  console.run_cycles(20000);
  return 0;
}
