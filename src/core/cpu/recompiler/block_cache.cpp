// The block cache (block_cache.h).
#include "core/cpu/recompiler/block_cache.h"

#include <algorithm>

namespace psx {

void BlockCache::insert(u32 pc, BlockFn fn, u32 first_page, u32 last_page, std::span<const BlockLinks::Site> sites) {
  blocks_[pc] = fn;
  links_.compiled(pc, reinterpret_cast<const void*>(fn));
  links_.add(pc, sites, [this](u32 target) {
    const auto it = blocks_.find(target);
    return it == blocks_.end() ? nullptr : reinterpret_cast<const void*>(it->second);
  });
  if (first_page == CodePages::kNoPage) return;
  if (page_blocks_.empty()) page_blocks_.resize(CodePages::kPages);
  page_blocks_[first_page].push_back(pc);
  if (last_page != first_page) page_blocks_[last_page].push_back(pc);
}

void BlockCache::invalidate_page(u32 page) {
  if (page_blocks_.empty()) return;
  for (u32 pc : page_blocks_[page]) erase(pc);
  page_blocks_[page].clear();
}

void BlockCache::erase(u32 pc) {
  blocks_.erase(pc);
  links_.dropped(pc);
  Recent& r = recent_[(pc >> 2) & (kRecent - 1)];
  if (r.pc == pc) r = Recent{};
}

void BlockCache::clear() {
  blocks_.clear();
  links_.clear();
  std::fill(recent_.begin(), recent_.end(), Recent{});  // in place: recent_table() stays valid
  for (auto& v : page_blocks_) v.clear();
}

}  // namespace psx
