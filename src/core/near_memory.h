// Host memory placed close to another object. x86-64 instructions address memory with a signed
// 32-bit displacement from a register: the recompiler's native loads and stores reach the
// console's RAM as [context + offset + displacement] when RAM lies within 2 GiB of the CPU, one
// instruction and 10 bytes shorter than loading RAM's 64-bit address first (the recompiler's
// Impl::host_at()). The allocator puts a large buffer at the other end of the address space from
// the heap, so NearMemory asks the kernel for pages near an anchor (the Bus, which lives beside
// the CPU in the Console) and takes pages anywhere when none are free there (as under
// AddressSanitizer, which reserves the space around its heap); nothing but speed depends on
// where they land.
#pragma once
#include <cstddef>

#include "core/types.h"

namespace psx {

class NearMemory {
 public:
  // `bytes` zeroed bytes, preferably within kReach of `anchor`. Throws std::bad_alloc when the
  // kernel has no pages at all.
  NearMemory(size_t bytes, const void* anchor);
  ~NearMemory();
  NearMemory(const NearMemory&) = delete;
  NearMemory& operator=(const NearMemory&) = delete;

  u8* data() { return data_; }
  const u8* data() const { return data_; }
  size_t size() const { return size_; }
  u8& operator[](size_t i) { return data_[i]; }
  const u8& operator[](size_t i) const { return data_[i]; }

  // How near counts as near: a quarter of the displacement's range, so that anything within a
  // few hundred MiB of the anchor (the CPU beside the Bus) still reaches every byte.
  static constexpr size_t kReach = size_t{1} << 29;

 private:
  u8* data_ = nullptr;
  size_t size_ = 0;
};

}  // namespace psx
