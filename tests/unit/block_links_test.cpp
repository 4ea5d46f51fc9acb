// The recompiler's direct jumps between blocks (core/cpu/recompiler/block_links.h): a link site
// is the rel32 of a near jump, which is 0 (on to the lookup after it) until its target's block
// exists, and then the distance from the end of the jump to the block's entry. Here the "code"
// is a plain byte array, so the expected fields are the arithmetic of those distances. The
// recompiler's use of them is checked against the interpreter in the last test.
#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <unordered_map>

#include "core/cpu/recompiler/block_links.h"
#include "recompiler_test_util.h"

namespace {

using psx::BlockLinks;
using psx::s32;
using psx::u32;
using psx::u8;

s32 rel32_at(const u8* p) {
  s32 v;
  std::memcpy(&v, p, 4);
  return v;
}

struct Buffer {
  std::array<u8, 4096> bytes{};
  std::unordered_map<u32, const void*> blocks;  // pc -> entry, what BlockCache would find
  auto find() {
    return [this](u32 pc) -> const void* {
      const auto it = blocks.find(pc);
      return it == blocks.end() ? nullptr : it->second;
    };
  }
};

TEST(BlockLinks, SiteWaitsForItsTargetThenJumpsToItsEntry) {
  Buffer b;
  BlockLinks links;
  // Block A (pc 0x100) at byte 0 with a site at byte 40 to pc 0x200, entered at offset 64.
  const BlockLinks::Site site{&b.bytes[40], 0x200, 64};
  b.blocks[0x100] = &b.bytes[0];
  links.add(0x100, {&site, 1}, b.find());
  EXPECT_EQ(rel32_at(&b.bytes[40]), 0);  // no block at 0x200 yet: on to the lookup
  b.blocks[0x200] = &b.bytes[1000];
  links.compiled(0x200, &b.bytes[1000]);
  EXPECT_EQ(rel32_at(&b.bytes[40]), 1000 + 64 - (40 + 4));
  links.dropped(0x200);  // the target dropped: back to the lookup
  EXPECT_EQ(rel32_at(&b.bytes[40]), 0);
  links.compiled(0x200, &b.bytes[2000]);  // compiled again elsewhere
  EXPECT_EQ(rel32_at(&b.bytes[40]), 2000 + 64 - 44);
  EXPECT_EQ(links.sites(), 1u);
}

TEST(BlockLinks, SiteToACompiledBlockJumpsAtOnce) {
  Buffer b;
  BlockLinks links;
  b.blocks[0x300] = &b.bytes[500];
  const BlockLinks::Site site{&b.bytes[10], 0x300, 264};
  links.add(0x400, {&site, 1}, b.find());
  EXPECT_EQ(rel32_at(&b.bytes[10]), 500 + 264 - 14);
}

TEST(BlockLinks, DroppedBlocksSitesAreForgotten) {
  Buffer b;
  BlockLinks links;
  // A (0x100) and C (0x300) both go on to B (0x200); A also to itself.
  const std::array<BlockLinks::Site, 2> a_sites = {BlockLinks::Site{&b.bytes[20], 0x200, 64},
                                                   BlockLinks::Site{&b.bytes[30], 0x100, 264}};
  const BlockLinks::Site c_site{&b.bytes[120], 0x200, 64};
  b.blocks[0x100] = &b.bytes[0];
  links.add(0x100, a_sites, b.find());
  EXPECT_EQ(rel32_at(&b.bytes[30]), 264 - 34);  // its own entry
  links.add(0x300, {&c_site, 1}, b.find());
  EXPECT_EQ(links.sites(), 3u);
  links.dropped(0x100);  // A's code is dead: its sites are not written again
  EXPECT_EQ(links.sites(), 1u);
  std::memset(&b.bytes[20], 0x5A, 4);
  links.compiled(0x200, &b.bytes[3000]);
  EXPECT_EQ(rel32_at(&b.bytes[20]), 0x5A5A5A5A);
  EXPECT_EQ(rel32_at(&b.bytes[120]), 3000 + 64 - 124);
  links.clear();
  EXPECT_EQ(links.sites(), 0u);
}

// Blocks in three code pages (256 bytes each) go on to each other: A to B, B to C, C back to A
// for 200 rounds (B counts them in s1) and then to a loop of its own (which idle skipping jumps
// over), and C rewrites B's first instruction (its immediate counts up) each round, so B's page is
// dropped and compiled again every round, and A's site to it goes back to its lookup each time.
// The recompiler must leave the machine as the interpreter does. A's and C's sites stay (B's is
// forgotten whenever B is dropped, which may be where the run ends).
TEST(BlockLinks, RecompiledTargetIsLinkedAgain) {
  using namespace recompiler_test;
  const u32 base = 0x80010000, kS2 = 18;
  std::vector<u32> code(0xC0, kNop);
  code[0x00] = j(base + 0x100);
  code[0x40] = itype(0x09, kS2, kS2, 1);  // B: addiu s2, s2, 1 (rewritten)
  code[0x41] = itype(0x09, kS1, kS1, 1);
  code[0x42] = j(base + 0x200);
  const u32 kT2 = 10;
  const std::vector<u32> c = {itype(0x0F, 0, kT0, 0x8001), itype(0x23, kT0, kT1, 0x100), kNop,
                              itype(0x09, kT1, kT1, 1), itype(0x2B, kT0, kT1, 0x100),
                              itype(0x0A, kS1, kT2, 200),    // slti t2, s1, 200
                              itype(0x05, kT2, 0, u32(-135)),  // bne t2, zero, A (base)
                              kNop, j(base + 0x220), kNop};  // then round itself at base + 220h
  std::copy(c.begin(), c.end(), code.begin() + 0x80);
  expect_same_code(code, base, 0, {}, 1);
  Console con;
  con.set_cpu_mode(Console::CpuMode::Recompiler);
  load_code(con, code, base, 0, {});
  con.run_frames(1);
  EXPECT_EQ(con.cpu().reg(kS1), 200u);
  EXPECT_GE(con.recompiler_stats().invalidated, 200u);
  EXPECT_GE(con.recompiler_link_sites(), 2u);
}

}  // namespace
