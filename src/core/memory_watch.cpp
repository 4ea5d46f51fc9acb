// Memory watches: range bookkeeping, fresh-only filtering and flow-limit coalescing.
#include "core/memory_watch.h"

#include <stdexcept>

#include "core/bus.h"

namespace psx {

namespace {
// Physical RAM offset (mirrors folded) or scratchpad address of a guest address, or ~0 if the
// address is neither.
u32 watch_address(u32 vaddr) {
  u32 p = Bus::physical(vaddr);
  if (p < 0x00800000) return p & (Bus::kRamSize - 1);
  if (p >= MemoryWatches::kScratchBase && p < MemoryWatches::kScratchBase + Bus::kScratchSize) return p;
  return ~0u;
}
}  // namespace

void MemoryWatches::watch(const std::string& key, u32 address, u32 length, bool fresh_only, u32 flow_limit_frames) {
  for (const Watch& w : watches_)
    if (w.key == key) throw std::invalid_argument("a memory watch named '" + key + "' already exists");
  u32 begin = watch_address(address);
  if (length == 0) throw std::invalid_argument("memory watch '" + key + "' has length 0");
  bool ram = begin < Bus::kRamSize;
  u32 limit = ram ? Bus::kRamSize : kScratchBase + Bus::kScratchSize;
  if (begin == ~0u || length > limit - begin)
    throw std::invalid_argument("memory watch '" + key + "' is not inside RAM or the scratchpad");
  Watch w;
  w.key = key;
  w.begin = begin;
  w.end = begin + length;
  w.fresh_only = fresh_only;
  w.flow_limit_frames = flow_limit_frames;
  watches_.push_back(std::move(w));
  rebuild_blocks();
}

void MemoryWatches::unwatch(const std::string& key) {
  for (size_t i = 0; i < watches_.size(); ++i)
    if (watches_[i].key == key) {
      watches_.erase(watches_.begin() + static_cast<long>(i));
      rebuild_blocks();
      return;
    }
  throw std::invalid_argument("no memory watch named '" + key + "'");
}

MemoryWatches::Watch& MemoryWatches::find(const std::string& key) {
  for (Watch& w : watches_)
    if (w.key == key) return w;
  throw std::invalid_argument("no memory watch named '" + key + "'");
}

void MemoryWatches::rebuild_blocks() {
  ram_blocks_.fill(0);
  for (const Watch& w : watches_)
    if (w.begin < Bus::kRamSize)
      for (u32 block = w.begin >> 5; block <= (w.end - 1) >> 5; ++block) ram_blocks_[block >> 6] |= u64(1) << (block & 63);
}

void MemoryWatches::on_write(u32 phys, u32 width, u32 old_value, u32 new_value, u64 frame, Cycles cycle) {
  for (Watch& w : watches_) {
    if (phys + width <= w.begin || phys >= w.end || w.asleep) continue;
    if (w.fresh_only && old_value == new_value) continue;
    WatchEvent e{w.key, phys, width, old_value, new_value, frame, cycle};
    if (w.flow_limit_frames == 0) {
      events_.push_back(std::move(e));
      continue;
    }
    if (frame >= w.window_start + w.flow_limit_frames) {
      w.window_start = frame;
      w.in_window = 0;
    }
    if (w.in_window < 2) {
      ++w.in_window;
      events_.push_back(std::move(e));
    } else if (!w.pending) {
      w.pending = true;
      w.coalesced = std::move(e);
    } else {
      w.coalesced.address = phys;
      w.coalesced.width = width;
      w.coalesced.new_value = new_value;
    }
  }
}

void MemoryWatches::on_frame(u64 frame, Cycles cycle) {
  for (Watch& w : watches_) {
    if (!w.pending || frame < w.window_start + w.flow_limit_frames) continue;
    // The window ended: its coalesced write is the first event of the next window.
    w.pending = false;
    w.coalesced.frame = frame;
    w.coalesced.cycle = cycle;
    events_.push_back(std::move(w.coalesced));
    w.window_start = frame;
    w.in_window = 1;
  }
}

}  // namespace psx
