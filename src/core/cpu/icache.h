// The R3000A's instruction cache (psx-spx "Memory Map", i-Cache; "Memory Control", FFFE0130h):
// 4 KiB, direct-mapped, 256 lines of 4 words indexed by address bits 11-4, each line tagged with
// physical address bits 31-12 and one valid bit per word. Only its tags are kept: instructions are
// always read from memory, so what it decides is how long a fetch takes.
#pragma once
#include <array>

#include "core/state.h"
#include "core/types.h"

namespace psx {

class ICache {
 public:
  static constexpr u32 kLines = 256;
  static constexpr u32 kTagMask = 0xFFFFF000;

  static u32 line(u32 vaddr) { return (vaddr >> 4) & (kLines - 1); }
  static u32 word(u32 vaddr) { return (vaddr >> 2) & 3; }

  bool hit(u32 vaddr, u32 phys) const {
    const u32 t = tags_[line(vaddr)];
    return ((t ^ phys) & kTagMask) == 0 && ((t >> word(vaddr)) & 1);
  }

  bool line_valid(u32 vaddr) const { return (tags_[line(vaddr)] & 0xF) == 0xF; }

  // A miss fills from the fetched word to the end of the line, no wrapping; IBLKSZ = 0 (2-word
  // refill) stops a fill entered at word 0 after word 1. A miss on a line whose tag matches (the
  // word's valid bit was clear) refills the whole line. Returns the number of words read.
  u32 fill(u32 vaddr, u32 phys, bool two_word_refill) {
    u32& t = tags_[line(vaddr)];
    if (((t ^ phys) & kTagMask) == 0) {
      t |= 0xF;
      return 4;
    }
    const u32 w = word(vaddr);
    const u32 n = (w == 0 && two_word_refill) ? 2 : 4 - w;
    t = (phys & kTagMask) | (((1u << n) - 1) << w);
    return n;
  }

  // A store with SR.IsC and BCC.TAG set writes the tag of the line it addresses: the address
  // bits from the store's address, the valid bits from the data's low 4 bits (so storing 0 at
  // each line's address invalidates the cache, as the BIOS's FlushCache does).
  void write_tag(u32 vaddr, u32 phys, u32 data) { tags_[line(vaddr)] = (phys & kTagMask) | (data & 0xF); }

  u32 tag(u32 line_index) const { return tags_[line_index]; }

  void do_state(StateIO& s) {
    s.section("ICAC", 1);
    s.pod(tags_);
    s.end_section("ICAC");
  }

 private:
  std::array<u32, kLines> tags_{};  // physical address bits 31-12 | valid bits 3-0
};

}  // namespace psx
