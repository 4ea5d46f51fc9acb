// Memory watches: the seed's memory listeners (§3.1.2-3.1.3), in-process and lossless. Every
// guest write into a watched range of RAM or scratchpad - CPU stores of each width and DMA - is
// seen in the bus's write path and queued as an event for the caller to take after a run call.
//   fresh_only         report only writes that change the stored value
//   flow_limit_frames  at most 2 events per window of this many frames; further writes in the
//                      window are coalesced into one event (first old value, last new value)
//                      delivered when the window ends (0 = no limit)
//   sleep/wake         a sleeping watch reports nothing and queues nothing
// Watches are observers configured by the host, not console state: save states do not hold them.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "core/types.h"

namespace psx {

struct WatchEvent {
  std::string key;
  u32 address;  // physical address written (RAM 0x00000000-0x001FFFFF, scratchpad 0x1F800000-...)
  u32 width;    // bytes written: 1, 2 or 4
  u32 old_value;
  u32 new_value;
  u64 frame;
  Cycles cycle;
};

class MemoryWatches {
 public:
  static constexpr u32 kScratchBase = 0x1F800000;

  // `address` may be any KUSEG/KSEG0/KSEG1 address of RAM (any mirror) or the scratchpad.
  // Throws std::invalid_argument for an empty range, a range outside RAM/scratchpad or a key
  // already in use.
  void watch(const std::string& key, u32 address, u32 length, bool fresh_only, u32 flow_limit_frames);
  void unwatch(const std::string& key);
  void sleep(const std::string& key) { find(key).asleep = true; }
  void wake(const std::string& key) { find(key).asleep = false; }
  bool empty() const { return watches_.empty(); }

  // Bus side: is this physical RAM offset in a 32-byte block that a watch touches? (a cheap
  // pre-check; aligned stores never straddle two blocks)
  bool ram_block_watched(u32 ram_offset) const {
    return (ram_blocks_[ram_offset >> 11] >> ((ram_offset >> 5) & 63)) & 1;
  }
  void on_write(u32 phys, u32 width, u32 old_value, u32 new_value, u64 frame, Cycles cycle);
  // Console side, at each frame boundary: delivers coalesced events whose window has ended.
  void on_frame(u64 frame, Cycles cycle);

  std::vector<WatchEvent> take_events() { return std::move(events_); }

 private:
  struct Watch {
    std::string key;
    u32 begin, end;  // physical [begin, end)
    bool fresh_only;
    u32 flow_limit_frames;
    bool asleep = false;
    u64 window_start = 0;
    u32 in_window = 0;
    bool pending = false;
    WatchEvent coalesced{};
  };
  Watch& find(const std::string& key);
  void rebuild_blocks();

  std::vector<Watch> watches_;
  std::vector<WatchEvent> events_;
  std::array<u64, 1024> ram_blocks_{};  // one bit per 32 bytes of the 2 MiB
};

}  // namespace psx
