// NearMemory (core/near_memory.h): zeroed pages placed near an anchor, and the console's RAM in
// them, within a 32-bit displacement of the console (and so of its CPU, which the recompiler's
// native loads and stores address RAM from). The anchors and the console lie in static storage,
// beside the test program's image: AddressSanitizer reserves the whole address space around its
// heap, so a heap anchor finds no pages near it there (the sanitizer pass), while around the
// program image every build has free space.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "core/console.h"
#include "core/near_memory.h"

namespace psx {
namespace {

std::intptr_t distance(const void* a, const void* b) {
  return reinterpret_cast<std::intptr_t>(a) - reinterpret_cast<std::intptr_t>(b);
}

alignas(64) std::array<u8, 4096> anchor;
constexpr size_t kBytes = 2 * 1024 * 1024 + 1024;  // RAM and the scratchpad

TEST(NearMemory, ZeroedWritableAndNearItsAnchor) {
  NearMemory m(kBytes, &anchor);
  ASSERT_EQ(m.size(), kBytes);
  EXPECT_TRUE(std::all_of(m.data(), m.data() + kBytes, [](u8 b) { return b == 0; }));
  m[0] = 1, m[kBytes - 1] = 2;
  EXPECT_EQ(m.data()[0] + m.data()[kBytes - 1], 3);
  EXPECT_LT(std::abs(distance(m.data(), &anchor)), std::intptr_t{NearMemory::kReach});
  EXPECT_LT(std::abs(distance(m.data() + kBytes, &anchor)), std::intptr_t{NearMemory::kReach});
}

TEST(NearMemory, ManyBuffersNearOneAnchor) {
  // A vector environment's consoles sit close together: each one's RAM must still find pages
  // near it, past the pages the others took.
  std::vector<std::unique_ptr<NearMemory>> buffers;
  for (int i = 0; i < 32; ++i) {
    buffers.push_back(std::make_unique<NearMemory>(kBytes, &anchor));
    EXPECT_LT(std::abs(distance(buffers.back()->data(), &anchor)), std::intptr_t{NearMemory::kReach}) << i;
  }
}

TEST(NearMemory, ConsoleRamIsWithinADisplacementOfTheConsole) {
  alignas(Console) static unsigned char storage[sizeof(Console)];
  Console* console = new (storage) Console();
  const std::span<u8> ram = console->ram();
  const std::intptr_t reach = INT32_MAX;  // a signed 32-bit displacement
  EXPECT_LT(std::abs(distance(ram.data(), console)), reach);
  EXPECT_LT(std::abs(distance(ram.data() + ram.size(), console)), reach);
  console->~Console();
}

}  // namespace
}  // namespace psx
