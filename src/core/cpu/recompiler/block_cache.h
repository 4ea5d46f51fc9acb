// Compiled blocks by the address of their first instruction, and for each RAM page the blocks
// whose code lies in it, so that a write to the page drops exactly those (code_pages.h).
#pragma once
#include <array>
#include <unordered_map>
#include <vector>

#include "core/cpu/recompiler/block_emitter.h"
#include "core/cpu/recompiler/code_pages.h"

namespace psx {

class BlockCache {
 public:
  using BlockFn = BlockEmitter::BlockFn;

  BlockFn find(u32 pc) const {
    auto it = blocks_.find(pc);
    return it == blocks_.end() ? nullptr : it->second;
  }
  // A block starting at pc whose instructions lie in pages first..last (CodePages::kNoPage for
  // code outside RAM).
  void insert(u32 pc, BlockFn fn, u32 first_page, u32 last_page);
  void invalidate_page(u32 page);
  void clear();
  size_t size() const { return blocks_.size(); }

 private:
  std::unordered_map<u32, BlockFn> blocks_;
  std::array<std::vector<u32>, CodePages::kPages> page_blocks_;
};

}  // namespace psx
