// HLE kernel: memory allocation (psx-spx "BIOS Memory Allocation"): the program heap of InitHeap/
// malloc/free/calloc/realloc (A0h:33h-39h) and the kernel's own small heap (B0h:00h/01h). Both
// live in guest RAM as a chain of blocks, each after a 4-byte header holding the payload size
// (a multiple of 4) with bit 0 set while the block is in use. Free neighbours merge as the
// allocator walks past them. A corrupted header ends the walk (an allocation then fails).
#include "core/bios/hle_bios.h"

namespace psx {

namespace {
constexpr u32 kA0r = 4, kA1 = 5;
constexpr u32 kA0 = 0xA0;
constexpr u32 kUsed = 1;
}  // namespace

u32 HleBios::heap_alloc(Heap& h, u32 size) {
  if (size > h.end - h.start) return 0;
  size = size ? (size + 3) & ~3u : 4;
  for (u32 p = h.start; p + 4 <= h.end;) {
    u32 head = peek32(p), len = head & ~3u;
    if (len > h.end - p - 4) return 0;
    if (head & kUsed) {
      p += 4 + len;
      continue;
    }
    // Merge the following free blocks into this one.
    for (u32 q = p + 4 + len; q + 4 <= h.end && !(peek32(q) & kUsed);) {
      u32 qlen = peek32(q) & ~3u;
      if (qlen > h.end - q - 4) break;
      len += 4 + qlen;
      q = p + 4 + len;
    }
    if (len >= size) {
      if (len - size >= 8) {
        poke32(p + 4 + size, len - size - 4);
        len = size;
      }
      poke32(p, len | kUsed);
      return p + 4;
    }
    poke32(p, len);
    p += 4 + len;
  }
  return 0;
}

void HleBios::heap_free(Heap& h, u32 ptr) {
  if (ptr < h.start + 4 || ptr >= h.end || (ptr & 3)) return;
  poke32(ptr - 4, peek32(ptr - 4) & ~kUsed);
}

u32 HleBios::heap_realloc(Heap& h, u32 ptr, u32 size) {
  if (!ptr) return heap_alloc(h, size);
  if (!size) {
    heap_free(h, ptr);
    return 0;
  }
  u32 old = peek32(ptr - 4) & ~3u;
  if (old >= size) return ptr;
  u32 fresh = heap_alloc(h, size);
  if (!fresh) return 0;
  for (u32 i = 0; i < old; ++i) poke8(fresh + i, peek8(ptr + i));
  heap_free(h, ptr);
  return fresh;
}

bool HleBios::memory_call(u32 table, u32 fn) {
  const u32 a0 = cpu_.reg(kA0r), a1 = cpu_.reg(kA1);
  if (table != kA0) {
    switch (fn) {
      case 0x00: return_to_caller(heap_alloc(kernel_heap_, a0)); return true;  // alloc_kernel_memory
      case 0x01: heap_free(kernel_heap_, a0); return_to_caller(0); return true;  // free_kernel_memory
      default: return false;
    }
  }
  switch (fn) {
    case 0x33: return_to_caller(heap_alloc(heap_, a0)); return true;
    case 0x34: heap_free(heap_, a0); return_to_caller(0); return true;
    case 0x37: {  // calloc(count, size)
      u64 total = static_cast<u64>(a0) * a1;
      u32 p = total > 0xFFFFFFFFu ? 0 : heap_alloc(heap_, static_cast<u32>(total));
      for (u32 i = 0; p && i < total; ++i) poke8(p + i, 0);
      return_to_caller(p);
      return true;
    }
    case 0x38: return_to_caller(heap_realloc(heap_, a0, a1)); return true;
    case 0x39: {  // InitHeap(addr, size): one free block over the whole area
      u32 start = (a0 + 3) & ~3u, end = (a0 + a1) & ~3u;
      heap_ = {start, end > start + 4 ? end : start};
      if (heap_.end > heap_.start) poke32(start, end - start - 4);
      return_to_caller(0);
      return true;
    }
    default: return false;
  }
}

}  // namespace psx
