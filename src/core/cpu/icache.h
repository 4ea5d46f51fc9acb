// The R3000A's instruction cache (psx-spx "Memory Map", i-Cache; "Memory Control", FFFE0130h):
// 4 KiB, direct-mapped, 256 lines of 4 words indexed by address bits 11-4, each line tagged with
// physical address bits 31-12 and one valid bit per word. A fill copies the words it reads from
// memory into the line, and a hit executes the copy: stores to RAM do not reach the cache, so
// code rewritten in RAM keeps running in its old form until its line is invalidated (the BIOS's
// FlushCache, tag writes under SR.IsC) or refilled for another address.
//
// Each tag also carries a bit the hardware does not have, kStale, for the recompiler: a line
// whose valid words may differ from the memory they were filled from. Compiled blocks hold only
// code that memory still holds (recompiler.h), so a line that is not stale and whose tag matches
// holds their words, and native code checks a line with one compare of its tag. The bit is set
// where code a block was compiled from is written (CodePages), where a tag write may have made
// any words valid (write_tag) and where a loaded state's words differ from memory, and cleared
// only by mark_stale_lines(), when the recompiler has dropped the blocks written. Nothing else
// sees it: hit() and tag() leave it out and save states do not hold it.
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
  static constexpr u32 kStale = 0x10;  // above the valid bits, below the address bits

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
      t = (phys & kTagMask) | (((1u << n) - 1) << first) | (t & kStale);
    }
    u32* dst = &words_[line(vaddr) * 4];
    for (u32 w = first; w < first + n; ++w) dst[w] = load_le32(mem + 4 * w);
    return n;
  }

  // A store with SR.IsC and BCC.TAG set writes the tag of the line it addresses: the address
  // bits from the store's address, the valid bits from the data's low 4 bits (so storing 0 at
  // each line's address invalidates the cache, as the BIOS's FlushCache does).
  // The words it makes valid are whatever the line held, so the line becomes stale.
  void write_tag(u32 vaddr, u32 phys, u32 data) {
    u32& t = tags_[line(vaddr)];
    t = (phys & kTagMask) | (data & 0xF) | (t & kStale) | (data & 0xF ? kStale : 0);
  }

  // Every line invalid, as FlushCache leaves the cache (its tag stores write address 0's tag).
  void invalidate_all() {
    for (u32& t : tags_) t &= kStale;
  }

  u32 tag(u32 line_index) const { return tags_[line_index] & ~kStale; }
  void mark_stale(u32 line_index) { tags_[line_index] |= kStale; }
  // Each line is stale exactly where one of its valid words differs from the memory at its
  // address: `mem(phys)` points at the word at a physical address, or is null where nothing
  // executable is.
  template <class Mem>
  void mark_stale_lines(Mem mem) {
    for (u32 l = 0; l < kLines; ++l) {
      u32& t = tags_[l];
      t &= ~kStale;
      for (u32 w = 0; w < 4; ++w) {
        if (!((t >> w) & 1)) continue;
        const u8* p = mem((t & kTagMask) | l << 4 | w << 2);
        if (!p || load_le32(p) != words_[l * 4 + w]) t |= kStale;
      }
    }
  }
  // The tags in place (tag(l) is tags()[l]), for the recompiler's native code.
  const u32* tags() const { return tags_.data(); }

  // Version 2 added the code words. Reading a version-1 section the caller refills the valid
  // words from memory (refill_valid): the state was made when a hit ran what memory held.
  static constexpr u32 kWordsSince = 2;
  // The caller marks stale lines after a load (mark_stale_lines()).
  u32 do_state(StateIO& s) {
    const u32 version = s.section("ICAC", 2, 1);
    std::array<u32, kLines> tags;
    for (u32 l = 0; l < kLines; ++l) tags[l] = tags_[l] & ~kStale;
    s.pod(tags);
    if (s.loading()) tags_ = tags;
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
