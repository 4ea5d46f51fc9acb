// NearMemory: anonymous pages (zeroed by the kernel) at a hinted address near the anchor.
#include "core/near_memory.h"

#include <sys/mman.h>

#include <cstdint>
#include <initializer_list>
#include <new>

namespace psx {

namespace {

void* map(void* hint, size_t bytes) {
  void* p = mmap(hint, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  return p == MAP_FAILED ? nullptr : p;
}

bool within(const void* p, size_t bytes, uintptr_t anchor) {
  const uintptr_t begin = reinterpret_cast<uintptr_t>(p), end = begin + bytes;
  return begin + NearMemory::kReach > anchor && end < anchor + NearMemory::kReach;
}

}  // namespace

NearMemory::NearMemory(size_t bytes, const void* anchor) : size_(bytes) {
  // A hint is only a wish: the kernel maps elsewhere when the range is taken (by another
  // console's RAM, in a vector environment), so hints go on in steps of kStep, below the anchor
  // first: above a heap anchor lies the space the heap grows into.
  constexpr uintptr_t kStep = uintptr_t{1} << 22;  // 4 MiB
  const uintptr_t a = reinterpret_cast<uintptr_t>(anchor) & ~(kStep - 1);
  const intptr_t steps = static_cast<intptr_t>((kReach - bytes) / kStep) - 1;
  for (const intptr_t dir : {-1, 1}) {
    for (intptr_t k = dir < 0 ? 1 : 2; k <= steps; ++k) {
      const uintptr_t hint = a + static_cast<uintptr_t>(dir * k * static_cast<intptr_t>(kStep));
      void* p = map(reinterpret_cast<void*>(hint), bytes);
      if (!p) throw std::bad_alloc();
      if (within(p, bytes, reinterpret_cast<uintptr_t>(anchor))) {
        data_ = static_cast<u8*>(p);
        return;
      }
      munmap(p, bytes);
    }
  }
  data_ = static_cast<u8*>(map(nullptr, bytes));
  if (!data_) throw std::bad_alloc();
}

NearMemory::~NearMemory() { munmap(data_, size_); }

}  // namespace psx
