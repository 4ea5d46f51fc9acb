// NearMemory (core/near_memory.h): zeroed pages placed near an anchor, and the console's RAM in
// them, within a 32-bit displacement of the console (and so of its CPU, which the recompiler's
// native loads and stores address RAM from). Not where AddressSanitizer reserves the address
// space around its heap, which leaves no pages near a heap anchor (the sanitizer pass).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include "core/console.h"
#include "core/near_memory.h"
#include "sanitizer_scale.h"

namespace psx {
namespace {

std::intptr_t distance(const void* a, const void* b) {
  return reinterpret_cast<std::intptr_t>(a) - reinterpret_cast<std::intptr_t>(b);
}

TEST(NearMemory, ZeroedWritableAndNearAHeapAnchor) {
  constexpr size_t kBytes = 2 * 1024 * 1024 + 1024;
  const auto anchor = std::make_unique<std::array<u8, 4096>>();
  NearMemory m(kBytes, anchor.get());
  ASSERT_EQ(m.size(), kBytes);
  EXPECT_TRUE(std::all_of(m.data(), m.data() + kBytes, [](u8 b) { return b == 0; }));
  m[0] = 1, m[kBytes - 1] = 2;
  EXPECT_EQ(m.data()[0] + m.data()[kBytes - 1], 3);
  if (test_scale::kSanitized) return;
  // Below the heap (or anywhere within kReach) the kernel has free pages in any usual process.
  EXPECT_LT(std::abs(distance(m.data(), anchor.get())), std::intptr_t{NearMemory::kReach});
  EXPECT_LT(std::abs(distance(m.data() + kBytes, anchor.get())), std::intptr_t{NearMemory::kReach});
}

TEST(NearMemory, ManyBuffersNearOneAnchor) {
  // A vector environment's consoles sit close together on the heap: each one's RAM must still
  // find pages near it, past the pages the others took.
  if (test_scale::kSanitized) GTEST_SKIP() << "AddressSanitizer reserves the space near its heap";
  constexpr size_t kBytes = 2 * 1024 * 1024 + 1024;
  const auto anchor = std::make_unique<std::array<u8, 4096>>();
  std::vector<std::unique_ptr<NearMemory>> buffers;
  for (int i = 0; i < 32; ++i) {
    buffers.push_back(std::make_unique<NearMemory>(kBytes, anchor.get()));
    EXPECT_LT(std::abs(distance(buffers.back()->data(), anchor.get())), std::intptr_t{NearMemory::kReach}) << i;
  }
}

TEST(NearMemory, ConsoleRamIsWithinADisplacementOfTheConsole) {
  if (test_scale::kSanitized) GTEST_SKIP() << "AddressSanitizer reserves the space near its heap";
  const auto console = std::make_unique<Console>();
  const std::span<u8> ram = console->ram();
  const std::intptr_t reach = INT32_MAX;  // a signed 32-bit displacement
  EXPECT_LT(std::abs(distance(ram.data(), console.get())), reach);
  EXPECT_LT(std::abs(distance(ram.data() + ram.size(), console.get())), reach);
}

}  // namespace
}  // namespace psx
