// Which words of RAM hold recompiled code, by 256-byte page (one bit per word), and which pages
// have had such a word written since they were compiled. The bus reports every CPU, DMA and host
// write to RAM here; the recompiler drops the blocks of the pages written before it runs another
// block. Until then the i-cache lines of every compiled word of a written page are stale
// (ICache::kStale), so that native code, which checks a line by its tag alone, leaves the blocks
// still running to their slow paths (recompiler.h).
#pragma once
#include <algorithm>
#include <utility>
#include <vector>

#include "core/cpu/icache.h"
#include "core/endian.h"
#include "core/types.h"

namespace psx {

class CodePages {
 public:
  CodePages() = default;
  CodePages(const CodePages&) = delete;  // any_dirty_ may point into this one
  CodePages& operator=(const CodePages&) = delete;
  static constexpr u32 kRamSize = 2 * 1024 * 1024;
  static constexpr u32 kScratchBytes = 1024;  // the scratchpad's, after RAM (Bus::scratchpad())
  // Word bits, so that stores to data next to code (a program's variables right after its code)
  // drop no blocks: recompiling is far dearer than a store. 64 words a page: one u64 of bits.
  static constexpr u32 kPageBits = 8;
  static constexpr u32 kPages = kRamSize >> kPageBits;
  // bits() has this many more u64s after RAM's pages, always zero: native stores address the
  // scratchpad as the 1 KiB after RAM (Bus::scratchpad()) and look its "pages" up there.
  static constexpr u32 kSparePages = kScratchBytes >> kPageBits;
  static constexpr u32 kNoPage = 0xFFFFFFFF;

  // The i-cache whose lines a write makes stale (the bus's; null: none).
  void watch(ICache* icache) { icache_ = icache; }

  // The RAM page holding the code at vaddr (KUSEG/KSEG0/KSEG1, RAM and its mirrors in the first
  // 8 MiB), or kNoPage (the BIOS ROM, which nothing writes).
  static u32 page_of(u32 vaddr) {
    const u32 p = vaddr >= 0x80000000 && vaddr < 0xC0000000 ? vaddr & 0x1FFFFFFF : vaddr;
    return p < 0x00800000 ? ram_offset(vaddr) >> kPageBits : kNoPage;
  }

  // The words from vaddr `first` to `last` (both in RAM, at most a page apart) hold compiled code.
  void mark_compiled(u32 first, u32 last) {
    for (u32 a = first; a != last + 4; a += 4) {
      const u32 off = ram_offset(a);
      code_[off >> kPageBits] |= u64{1} << ((off >> 2) & 63);
    }
  }
  // Whether the word at vaddr (as page_of() maps it) lies in a compiled block.
  bool compiled(u32 vaddr) const {
    const u32 page = page_of(vaddr);
    return page != kNoPage && (code_[page] >> ((ram_offset(vaddr) >> 2) & 63)) & 1;
  }
  // A write at RAM offset `off` (0 to 2 MiB - 1; every write stays within one word).
  void on_ram_write(u32 off) {
    u64& bits = code_[off >> kPageBits];
    if (!((bits >> ((off >> 2) & 63)) & 1)) return;
    written(off >> kPageBits);
  }
  // Writes to the `bytes` bytes from RAM offset `off` (word-aligned, not past RAM's end), as
  // on_ram_write() for each word, a page at a time (a DMA into RAM).
  void on_ram_range(u32 off, u32 bytes) {
    for (const u32 end = off + bytes; off < end;) {
      const u32 page = off >> kPageBits, page_end = std::min(end, (page + 1) << kPageBits);
      const u32 words = (page_end - off) >> 2;
      const u64 mask = (words == 64 ? ~u64{0} : (u64{1} << words) - 1) << ((off >> 2) & 63);
      if (code_[page] & mask) written(page);
      off = page_end;
    }
  }
  // A state is about to replace RAM (`ram`, 2 MiB) without writes being reported: the compiled
  // words as they are, for written_by_load() to compare once it has.
  std::vector<std::pair<u32, u32>> compiled_words(const u8* ram) const {
    std::vector<std::pair<u32, u32>> out;
    for (u32 page = 0; page < kPages; ++page)
      for (u64 bits = code_[page]; bits != 0; bits &= bits - 1) {
        const u32 off = page << kPageBits | u32(__builtin_ctzll(bits)) << 2;
        out.emplace_back(off, load_le32(ram + off));
      }
    return out;
  }
  // Each compiled word that the state loaded changed counts as written.
  void written_by_load(const u8* ram, const std::vector<std::pair<u32, u32>>& before) {
    for (const auto& [off, word] : before)
      if (load_le32(ram + off) != word) on_ram_write(off);
  }
  // The word bits in place (kPages + kSparePages u64s, never reallocated), for native stores,
  // which call on_ram_write() only for a word whose bit is set.
  const u64* bits() const { return code_.data(); }
  bool any_dirty() const { return *any_dirty_; }
  // any_dirty() in place, for compiled blocks that go on to the next block themselves.
  const bool* any_dirty_cell() const { return any_dirty_; }
  // Keeps any_dirty() at `cell` from now on (the CPU's, next to what blocks test with it).
  void keep_flag_at(bool* cell) {
    *cell = *any_dirty_;
    any_dirty_ = cell;
  }
  // The pages written since the last call, each once.
  std::vector<u32> take_dirty() {
    std::vector<u32> out;
    out.swap(dirty_);
    *any_dirty_ = false;
    return out;
  }
  void clear() {
    std::fill(code_.begin(), code_.end(), 0);  // in place: bits() stays valid
    dirty_.clear();
    *any_dirty_ = false;
  }

 private:
  static u32 ram_offset(u32 vaddr) {
    const u32 p = vaddr >= 0x80000000 && vaddr < 0xC0000000 ? vaddr & 0x1FFFFFFF : vaddr;
    return p & (kRamSize - 1);
  }
  // The page's compiled words are written: its blocks are dropped before the next block runs,
  // and their i-cache lines are stale until then (RAM offset o is on line (o >> 4) % 256).
  void written(u32 page) {
    if (icache_) {
      const u64 bits = code_[page];
      for (u32 l = 0; l < 16; ++l)
        if ((bits >> (4 * l)) & 0xF) icache_->mark_stale(ICache::line(page << kPageBits | l << 4));
    }
    code_[page] = 0;
    dirty_.push_back(page);
    *any_dirty_ = true;
  }

  std::vector<u64> code_ = std::vector<u64>(kPages + kSparePages);  // bit w of page p: word p * 64 + w
  std::vector<u32> dirty_;
  bool own_flag_ = false;
  bool* any_dirty_ = &own_flag_;  // !dirty_.empty()
  ICache* icache_ = nullptr;
};

}  // namespace psx
