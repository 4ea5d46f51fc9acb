// The instruction cache as the bus charges it (psx-spx "Memory Map", i-Cache; "Memory Control",
// FFFE0130h): what tests/roms/cpu_icache cannot reach from a program loaded into RAM. Costs: a
// fill reads each word it fills at the uncached fetch cost, 4 cycles from RAM, and from the BIOS
// ROM the 32-bit read time of its Delay/Size setting (7 + 3 * 6 = 25 cycles, the instruction's
// own cycle not counted: 24; see memory_control_test). A fill copies the words it reads; a hit
// returns the copy, whatever memory holds since.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/bus.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "core/state.h"

namespace psx {
namespace {

struct Rig {
  Scheduler sched;
  InterruptController irq;
  Bus bus{sched, irq};
  // Cycles one fetch charges.
  Cycles fetch(u32 vaddr) {
    Cycles t0 = sched.now();
    u32 w;
    EXPECT_TRUE(bus.fetch(vaddr, w));
    return sched.now() - t0;
  }
  u32 code(u32 vaddr) {
    u32 w = 0;
    EXPECT_TRUE(bus.fetch(vaddr, w));
    return w;
  }
  void poke(u32 phys, u32 w) { store_le32(bus.ram() + phys, w); }
};

TEST(BusICache, FillFromTheFetchedWordToTheLineEnd) {
  Rig r;
  EXPECT_EQ(r.fetch(0x80010008), 2u * 4) << "entered at word 2: words 2 and 3";
  EXPECT_EQ(r.fetch(0x8001000C), 0u);
  EXPECT_EQ(r.fetch(0x80010000), 4u * 4) << "word 0 invalid under a matching tag: whole-line refill";
  EXPECT_EQ(r.fetch(0x80010004), 0u);
  EXPECT_EQ(r.fetch(0xA0010004), 4u) << "KSEG1 is never cached";
}

TEST(BusICache, BiosRomFillsAtTheRomReadTime) {
  Rig r;
  const Cycles word = r.bus.read_cycles(Bus::kBiosDelay, 4);
  ASSERT_EQ(word, 24u);
  EXPECT_EQ(r.fetch(0x9FC00000), 4 * word);
  EXPECT_EQ(r.fetch(0x9FC0000C), 0u);
  EXPECT_EQ(r.fetch(0xBFC00000), word);
}

TEST(BusICache, IsolatedStoresWriteTagsOnlyInTagMode) {
  Rig r;
  r.fetch(0x80010000);
  r.bus.write32(0xFFFE0130, 0x800);  // IS1 only: code-word stores, tags untouched
  r.bus.isolated_store(0x00010000, 0);
  EXPECT_EQ(r.fetch(0x80010000), 0u);
  r.bus.write32(0xFFFE0130, 0x804);  // TAG | IS1
  r.bus.isolated_store(0x00010000, 0);
  EXPECT_EQ(r.bus.icache().tag(ICache::line(0x10000)), 0x00010000u);
  EXPECT_EQ(r.fetch(0x80010000), 4u * 4);
}

TEST(BusICache, HitsRunTheCachedCopy) {
  Rig r;
  r.poke(0x10000, 0x11111111);
  r.poke(0x1000C, 0x22222222);
  EXPECT_EQ(r.code(0x80010000), 0x11111111u);
  r.poke(0x10000, 0x33333333);
  r.poke(0x1000C, 0x44444444);
  EXPECT_EQ(r.code(0x80010000), 0x11111111u) << "a store does not reach the cache";
  EXPECT_EQ(r.code(0x8001000C), 0x22222222u) << "the fill copied the whole line";
  EXPECT_EQ(r.code(0x00010000), 0x11111111u) << "KUSEG shares KSEG0's lines";
  EXPECT_EQ(r.code(0xA0010000), 0x33333333u) << "KSEG1 reads memory";
  u32 w = 0;
  ASSERT_TRUE(r.bus.peek_code(0x80010000, w));
  EXPECT_EQ(w, 0x11111111u) << "peek_code sees what a fetch would run";
  r.bus.flush_icache();
  ASSERT_TRUE(r.bus.peek_code(0x80010000, w));
  EXPECT_EQ(w, 0x33333333u);
  EXPECT_EQ(r.fetch(0x80010000), 4u * 4) << "FlushCache leaves every line invalid";
  EXPECT_EQ(r.code(0x80010000), 0x33333333u);
}

TEST(BusICache, AnotherAddressEvictsTheLine) {
  Rig r;
  r.poke(0x10000, 0x11111111);
  r.code(0x80010000);
  r.poke(0x10000, 0x22222222);
  r.code(0x80011000);  // same line index (address bits 11-4), another tag
  EXPECT_EQ(r.code(0x80010000), 0x22222222u);
}

TEST(BusICache, TagsAndWordsSurviveASaveState) {
  Rig a;
  a.poke(0x10004, 0x12345678);
  a.fetch(0x80010000);
  a.poke(0x10004, 0);  // the cache now holds what memory no longer does
  StateIO w;
  a.bus.do_state(w);
  Rig b;
  StateIO rd(w.buffer().data(), w.buffer().size());
  b.bus.do_state(rd);
  EXPECT_EQ(b.fetch(0x80010004), 0u);
  EXPECT_EQ(b.code(0x80010004), 0x12345678u);
  EXPECT_EQ(b.fetch(0x80020000), 4u * 4);
}

// An ICAC version-1 section (tags only, saved when a hit ran what memory held): loading it fills
// the valid words from memory. The section is made from a version-2 one by dropping the words.
TEST(BusICache, Version1StateRefillsValidWordsFromMemory) {
  Rig a;
  a.poke(0x10000, 0xAAAA0000);
  a.poke(0x1000C, 0xAAAA000C);
  a.fetch(0x80010008);  // words 2-3 valid
  StateIO w;
  a.bus.do_state(w);
  std::vector<u8> v1 = w.buffer();
  const u8 tag[4] = {'I', 'C', 'A', 'C'};
  const size_t at = std::search(v1.begin(), v1.end(), tag, tag + 4) - v1.begin();
  ASSERT_LT(at, v1.size());
  constexpr size_t kWordBytes = ICache::kLines * 4 * 4;
  const size_t words_at = at + 12 + ICache::kLines * 4;
  v1.erase(v1.begin() + words_at, v1.begin() + words_at + kWordBytes);
  store_le32(&v1[at + 4], 1);                                             // version
  store_le32(&v1[at + 8], load_le32(&v1[at + 8]) - kWordBytes);          // ICAC length
  store_le32(&v1[8], load_le32(&v1[8]) - kWordBytes);                    // BUS length
  Rig b;
  StateIO rd(v1.data(), v1.size());
  b.bus.do_state(rd);
  EXPECT_EQ(b.fetch(0x8001000C), 0u);
  EXPECT_EQ(b.code(0x8001000C), 0xAAAA000Cu);
  EXPECT_EQ(b.fetch(0x80010000), 4u * 4) << "word 0 was not valid";
}

}  // namespace
}  // namespace psx
