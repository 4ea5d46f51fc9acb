// Direct jumps between compiled blocks (block_links.h).
#include "core/cpu/recompiler/block_links.h"

#include <algorithm>
#include <cstring>

namespace psx {

// The code buffer is written and executed in place (xbyak's read-write-execute buffer), and only
// the thread running the console compiles or runs its blocks, so a site is rewritten between two
// runs of compiled code. The buffer is 16 MiB: every displacement fits in 32 bits.
void BlockLinks::point(const Site& s, const u8* to) {
  const s32 rel = static_cast<s32>(to - (s.rel32 + 4));
  std::memcpy(s.rel32, &rel, sizeof rel);
}

void BlockLinks::compiled(u32 pc, const void* code) {
  const auto it = by_target_.find(pc);
  if (it == by_target_.end()) return;
  for (const Owned& o : it->second) point(o.site, static_cast<const u8*>(code) + o.site.entry);
}

void BlockLinks::dropped(u32 pc) {
  if (const auto it = by_target_.find(pc); it != by_target_.end())
    for (const Owned& o : it->second) unlink(o.site);
  const auto own = owned_.find(pc);
  if (own == owned_.end()) return;
  for (u32 target : own->second) {
    std::vector<Owned>& v = by_target_[target];
    v.erase(std::remove_if(v.begin(), v.end(), [pc](const Owned& o) { return o.owner == pc; }), v.end());
    if (v.empty()) by_target_.erase(target);
  }
  owned_.erase(own);
}

void BlockLinks::clear() {
  by_target_.clear();
  owned_.clear();
}

size_t BlockLinks::sites() const {
  size_t n = 0;
  for (const auto& [target, v] : by_target_) n += v.size();
  return n;
}

}  // namespace psx
