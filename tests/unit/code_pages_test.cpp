// CodePages (cpu/recompiler/code_pages.h): which writes to RAM drop compiled code. A page is 256
// bytes (64 words, one bit each); a write to a word holding compiled code marks its page dirty
// once and forgets the page's words, and a DMA's range of words does the same as its words one by
// one.
#include <gtest/gtest.h>

#include <vector>

#include "core/cpu/recompiler/code_pages.h"

namespace psx {
namespace {

std::vector<u32> dirty_after(CodePages& pages) { return pages.take_dirty(); }

TEST(CodePages, WordWritesDropOnlyPagesWithCompiledWords) {
  CodePages pages;
  pages.mark_compiled(0x80010100, 0x80010108);  // page 0x101, words 0-2
  pages.on_ram_write(0x1010C);                   // word 3: data after the code
  EXPECT_FALSE(pages.any_dirty());
  pages.on_ram_write(0x10104);
  EXPECT_EQ(dirty_after(pages), std::vector<u32>{0x101});
  pages.on_ram_write(0x10100);  // the page's words were forgotten with the first write
  EXPECT_FALSE(pages.any_dirty());
}

TEST(CodePages, RangesDropEachPageTheyTouchOnce) {
  CodePages pages;
  pages.mark_compiled(0x000200FC, 0x000200FC);  // page 0x200, its last word
  pages.mark_compiled(0x00020100, 0x00020100);  // page 0x201, its first word
  pages.mark_compiled(0x00020380, 0x00020380);  // page 0x203, word 32
  pages.mark_compiled(0x001FFFFC, 0x001FFFFC);  // the last page of RAM, its last word
  pages.on_ram_range(0x20000, 0xFC);  // page 0x200 up to its last word, which it leaves alone
  EXPECT_FALSE(pages.any_dirty());
  pages.on_ram_range(0x200F8, 0x10);  // 0x200F8..0x20107: pages 0x200 and 0x201
  EXPECT_EQ(dirty_after(pages), (std::vector<u32>{0x200, 0x201}));
  pages.on_ram_range(0x20200, 0x100);  // all of page 0x202, nothing compiled there
  pages.on_ram_range(0x20384, 0x7C);   // page 0x203 from word 33 on
  EXPECT_FALSE(pages.any_dirty());
  pages.on_ram_range(0x20300, 0x100);
  EXPECT_EQ(dirty_after(pages), std::vector<u32>{0x203});
  pages.on_ram_range(0x1FFF00, 0x100);  // the whole last page, up to RAM's end
  EXPECT_EQ(dirty_after(pages), std::vector<u32>{0x1FFF});
}

}  // namespace
}  // namespace psx
