// Compiled blocks by the address of their first instruction, and for each RAM page the blocks
// whose code lies in it, so that a write to the page drops exactly those (code_pages.h). A small
// direct-mapped table in front of the hash map answers most lookups. The blocks' direct jumps to
// each other (block_links.h) follow the blocks in and out.
#pragma once
#include <cstddef>
#include <span>
#include <unordered_map>
#include <vector>

#include "core/cpu/recompiler/block_emitter.h"
#include "core/cpu/recompiler/block_links.h"
#include "core/cpu/recompiler/code_pages.h"

namespace psx {

class BlockCache {
 public:
  using BlockFn = BlockEmitter::BlockFn;

  BlockFn find(u32 pc) {
    Recent& r = recent_[(pc >> 2) & (kRecent - 1)];
    if (r.pc == pc) return r.fn;
    auto it = blocks_.find(pc);
    if (it == blocks_.end()) return nullptr;
    r = {pc, it->second};
    return it->second;
  }
  // A block starting at pc whose instructions lie in pages first..last (CodePages::kNoPage for
  // code outside RAM), with its link sites.
  void insert(u32 pc, BlockFn fn, u32 first_page, u32 last_page, std::span<const BlockLinks::Site> sites = {});
  void invalidate_page(u32 page);
  // find()'s direct-mapped table in place, for compiled blocks that go on to the next block
  // themselves: kRecent entries of {u32 pc; BlockFn fn at byte 8}, entry (pc >> 2) & (kRecent - 1).
  static constexpr u32 kRecent = 4096;
  const void* recent_table() const { return recent_.data(); }
  void clear();
  size_t size() const { return blocks_.size(); }
  size_t link_sites() const { return links_.sites(); }

 private:
  void erase(u32 pc);

  struct Recent {
    u32 pc = 1;  // never a block's (aligned) address
    BlockFn fn = nullptr;
  };
  static_assert(sizeof(Recent) == 16 && offsetof(Recent, fn) == 8);
  std::vector<Recent> recent_ = std::vector<Recent>(kRecent);  // never reallocated
  std::unordered_map<u32, BlockFn> blocks_;
  std::vector<std::vector<u32>> page_blocks_;  // sized on the first insert
  BlockLinks links_;
};

}  // namespace psx
