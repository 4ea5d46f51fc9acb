// WrittenPages (core/written_pages.h): which 256-byte pages of RAM and the scratchpad were written
// since they last matched a snapshot. The pages and bytes copied back are the arithmetic of the
// 256-byte page: byte n lies in page n >> 8, and the scratchpad's 1 KiB after RAM's 2 MiB are
// pages 8192 to 8195.
#include <gtest/gtest.h>

#include <vector>

#include "core/written_pages.h"

namespace {

using psx::u8;
using psx::WrittenPages;

// Every page written until cleared; then each mark covers exactly its pages.
TEST(WrittenPages, MarksThePagesOfEachWrite) {
  WrittenPages w;
  EXPECT_EQ(WrittenPages::kPages, 8196u);
  EXPECT_TRUE(w.any());  // nothing is known to match anything yet
  w.clear();
  EXPECT_FALSE(w.any());
  w.mark(0x1FF);  // page 1
  w.mark_range(0x2FE, 4);  // pages 2 and 3
  w.mark(WrittenPages::kRamSize + 0x3FC);  // the scratchpad's last page, 8195
  const u8* p = w.data();
  for (unsigned page = 0; page < WrittenPages::kPages; ++page)
    EXPECT_EQ(p[page], page == 1 || page == 2 || page == 3 || page == 8195 ? 1 : 0) << "page " << page;
}

// copy_back() copies the pages marked, whole, from the source, leaves the others as they are
// and clears the marks.
TEST(WrittenPages, CopyBackCopiesThePagesWrittenAndClears) {
  WrittenPages w;
  w.clear();
  std::vector<u8> now(WrittenPages::kBytes, 0xAA), snap(WrittenPages::kBytes, 0x55);
  w.mark(0x100);  // page 1
  w.mark(0x200);  // page 2, one run with page 1
  w.mark(0x1000);  // page 16
  w.mark(WrittenPages::kBytes - 1);  // the last page
  w.copy_back(now.data(), snap.data());
  for (size_t i = 0; i < now.size(); ++i) {
    const size_t page = i >> 8;
    const bool copied = page == 1 || page == 2 || page == 16 || page == WrittenPages::kPages - 1;
    ASSERT_EQ(now[i], copied ? 0x55 : 0xAA) << "byte " << i;
  }
  EXPECT_FALSE(w.any());
}

}  // namespace
