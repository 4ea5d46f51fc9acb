// Which 4 KiB pages of RAM hold recompiled code, and which of those have been written since they
// were compiled. The bus reports every CPU and DMA write to RAM here; the recompiler drops the
// blocks of the pages written before it runs another block. (Compiled blocks stay exact even when
// stale, recompiler.h, so this keeps the block cache current rather than making it correct.)
#pragma once
#include <array>
#include <vector>

#include "core/types.h"

namespace psx {

class CodePages {
 public:
  static constexpr u32 kRamSize = 2 * 1024 * 1024;
  static constexpr u32 kPageBits = 12;
  static constexpr u32 kPages = kRamSize >> kPageBits;
  static constexpr u32 kNoPage = 0xFFFFFFFF;

  // The RAM page holding the code at vaddr (KUSEG/KSEG0/KSEG1, RAM and its mirrors in the first
  // 8 MiB), or kNoPage (the BIOS ROM, which nothing writes).
  static u32 page_of(u32 vaddr) {
    const u32 p = vaddr >= 0x80000000 && vaddr < 0xC0000000 ? vaddr & 0x1FFFFFFF : vaddr;
    return p < 0x00800000 ? (p & (kRamSize - 1)) >> kPageBits : kNoPage;
  }

  void mark_compiled(u32 page) { compiled_[page] = true; }
  // A write at RAM offset `off` (0 to 2 MiB - 1).
  void on_ram_write(u32 off) {
    const u32 page = off >> kPageBits;
    if (!compiled_[page]) return;
    compiled_[page] = false;
    dirty_.push_back(page);
  }
  bool any_dirty() const { return !dirty_.empty(); }
  // The pages written since the last call, each once.
  std::vector<u32> take_dirty() {
    std::vector<u32> out;
    out.swap(dirty_);
    return out;
  }
  void clear() {
    compiled_.fill(false);
    dirty_.clear();
  }

 private:
  std::array<bool, kPages> compiled_{};
  std::vector<u32> dirty_;
};

}  // namespace psx
