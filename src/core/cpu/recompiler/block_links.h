// Direct jumps between compiled blocks. A block's end whose next pc is known when it is compiled
// (a branch's or jump's target, a fall-through) goes on through a jump of its own, a link site:
// until that pc's block exists the jump goes nowhere (its next instruction, the lookup in the
// recent table, block_emitter_chain.cpp), and from then on straight to the block. BlockCache
// keeps the sites of its blocks here: a block compiled takes the sites waiting for its pc, and a
// block dropped sends the sites jumping to it back to their lookup and forgets its own.
#pragma once
#include <span>
#include <unordered_map>
#include <vector>

#include "core/types.h"

namespace psx {

class BlockLinks {
 public:
  // A link site: the rel32 field of a near jump (E9 rel32) in a block's code, the pc it goes on
  // to and the offset in that pc's block it enters at (BlockEmitter::Impl::kCleanEntry or
  // kPrologueBytes).
  struct Site {
    u8* rel32;
    u32 target;
    u32 entry;
  };

  // The sites of the block just compiled at `owner`. Each jumps to its target's block at once
  // where `find` (u32 pc -> code or null) names one.
  template <class Find>
  void add(u32 owner, std::span<const Site> sites, Find find) {
    for (const Site& s : sites) {
      by_target_[s.target].push_back({s, owner});
      owned_[owner].push_back(s.target);
      if (const void* code = find(s.target)) point(s, static_cast<const u8*>(code) + s.entry);
    }
  }
  // The block at pc, just compiled: the sites waiting for it jump there.
  void compiled(u32 pc, const void* code);
  // The block at pc, dropped: the sites jumping to it go back to their lookup, and its own sites
  // (dead code now) are forgotten.
  void dropped(u32 pc);
  // Every block dropped (the code buffer emptied).
  void clear();
  size_t sites() const;

 private:
  struct Owned {
    Site site;
    u32 owner;
  };
  static void point(const Site& s, const u8* to);
  static void unlink(const Site& s) { point(s, s.rel32 + 4); }
  std::unordered_map<u32, std::vector<Owned>> by_target_;
  std::unordered_map<u32, std::vector<u32>> owned_;  // owner -> its sites' targets
};

}  // namespace psx
