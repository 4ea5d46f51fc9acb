// The R3000A's instruction cache (psx-spx "Memory Map", i-Cache; "Memory Control", FFFE0130h):
// 4 KiB, direct-mapped, 256 lines of 4 words indexed by address bits 11-4, each line tagged with
// physical address bits 31-12 and one valid bit per word. A fill copies the words it reads from
// memory into the line, and a hit executes the copy: stores to RAM do not reach the cache, so
// code rewritten in RAM keeps running in its old form until its line is invalidated (the BIOS's
// FlushCache, tag writes under SR.IsC) or refilled for another address.
#pragma once
#include <array>

#include "core/endian.h"
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

  // The cached copy of the instruction at vaddr (meaningful on a hit).
  u32 code(u32 vaddr) const { return words_[(vaddr >> 2) & (kLines * 4 - 1)]; }
  // The cached copies in place (code(vaddr) is words()[(vaddr >> 2) & 1023]), for the
  // recompiler's native code.
  const u32* words() const { return words_.data(); }

  // A miss fills from the fetched word to the end of the line, no wrapping; IBLKSZ = 0 (2-word
  // refill) stops a fill entered at word 0 after word 1. A miss on a line whose tag matches (the
  // word's valid bit was clear) refills the whole line. `mem` is the memory holding the line's
  // 16 bytes (little-endian words). Returns the number of words read.
  u32 fill(u32 vaddr, u32 phys, bool two_word_refill, const u8* mem) {
    u32& t = tags_[line(vaddr)];
    u32 first = 0, n = 4;
    if (((t ^ phys) & kTagMask) == 0) {
      t |= 0xF;
    } else {
      first = word(vaddr);
      n = (first == 0 && two_word_refill) ? 2 : 4 - first;
      t = (phys & kTagMask) | (((1u << n) - 1) << first);
    }
    u32* dst = &words_[line(vaddr) * 4];
    for (u32 w = first; w < first + n; ++w) dst[w] = load_le32(mem + 4 * w);
    return n;
  }

  // A store with SR.IsC and BCC.TAG set writes the tag of the line it addresses: the address
  // bits from the store's address, the valid bits from the data's low 4 bits (so storing 0 at
  // each line's address invalidates the cache, as the BIOS's FlushCache does).
  void write_tag(u32 vaddr, u32 phys, u32 data) { tags_[line(vaddr)] = (phys & kTagMask) | (data & 0xF); }

  // Every line invalid, as FlushCache leaves the cache (its tag stores write address 0's tag).
  void invalidate_all() { tags_.fill(0); }

  u32 tag(u32 line_index) const { return tags_[line_index]; }
  // The tags in place (tag(l) is tags()[l]), for the recompiler's native code.
  const u32* tags() const { return tags_.data(); }

  // Version 2 added the code words. Reading a version-1 section the caller refills the valid
  // words from memory (refill_valid): the state was made when a hit ran what memory held.
  static constexpr u32 kWordsSince = 2;
  u32 do_state(StateIO& s) {
    const u32 version = s.section("ICAC", 2, 1);
    s.pod(tags_);
    s.pod_since(version, kWordsSince, words_, decltype(words_){});
    s.end_section("ICAC");
    return version;
  }
  // Copies each valid word from memory: `mem(phys)` points at the word at a physical address, or
  // is null where nothing executable is (a tag written under isolation may name any address).
  template <class Mem>
  void refill_valid(Mem mem) {
    for (u32 l = 0; l < kLines; ++l)
      for (u32 w = 0; w < 4; ++w)
        if ((tags_[l] >> w) & 1)
          if (const u8* p = mem((tags_[l] & kTagMask) | l << 4 | w << 2)) words_[l * 4 + w] = load_le32(p);
  }

 private:
  std::array<u32, kLines> tags_{};  // physical address bits 31-12 | valid bits 3-0
  std::array<u32, kLines * 4> words_{};
};

}  // namespace psx
