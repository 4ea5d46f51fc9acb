// Which 256-byte pages of RAM and of the scratchpad after it (Bus::scratchpad()) have been written
// since they last matched a snapshot, so that restoring that snapshot copies those pages alone
// (Bus::do_state(), Console::restore()). An environment resets to its start state hundreds of
// times, and a game writes a few hundred KiB of its 2 MiB between two resets. Every CPU, DMA and
// host write reports here (the bus's write paths, Bus::host_wrote_ram() and
// host_wrote_scratchpad()), and the recompiler's native stores set their page's byte themselves
// (Impl::store()); a page's byte is 1 once it is written.
#pragma once
#include <algorithm>
#include <array>
#include <cstring>

#include "core/cpu/recompiler/code_pages.h"
#include "core/types.h"

namespace psx {

class WrittenPages {
 public:
  // The code pages' pages (native stores index both with one page number), RAM's and the
  // scratchpad's after them.
  static constexpr u32 kPageBits = CodePages::kPageBits;
  static constexpr u32 kRamSize = CodePages::kRamSize;
  static constexpr u32 kBytes = kRamSize + CodePages::kScratchBytes;
  static constexpr u32 kPages = CodePages::kPages + CodePages::kSparePages;

  WrittenPages() { mark_all(); }

  // A write of at most a word at `off` (0 to kBytes - 1, the scratchpad from kRamSize).
  void mark(u32 off) { pages_[off >> kPageBits] = 1; }
  // Writes to the `bytes` bytes from `off` (not past kBytes).
  void mark_range(u32 off, u32 bytes) {
    if (bytes == 0) return;
    const u32 first = off >> kPageBits, last = (off + bytes - 1) >> kPageBits;
    std::fill(pages_.begin() + first, pages_.begin() + last + 1, u8{1});
  }
  void mark_all() { pages_.fill(1); }
  void clear() { pages_.fill(0); }
  bool any() const {
    return std::any_of(pages_.begin(), pages_.end(), [](u8 b) { return b != 0; });
  }
  // Copies the pages written from `from` (kBytes, laid out as `to`) into `to`, and clears them.
  // Neighbouring pages written go as one copy.
  void copy_back(u8* to, const u8* from) {
    for (u32 p = 0; p < kPages;) {
      if (!pages_[p]) {
        ++p;
        continue;
      }
      u32 end = p;
      while (end < kPages && pages_[end]) pages_[end++] = 0;
      const u32 start = p << kPageBits, stop = std::min(end << kPageBits, kBytes);
      std::memcpy(to + start, from + start, stop - start);
      p = end;
    }
  }
  // The bytes native code sets, one per page.
  u8* data() { return pages_.data(); }

 private:
  std::array<u8, kPages> pages_{};
};

}  // namespace psx
