// compat_shift (cli/compat_run.h): the shift between two runs' last frame hashes, on sequences
// made by hand, so the expected shift is the one built into them.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "cli/compat_run.h"

namespace {

using psxrl::cli::compat_shift;
using Hashes = std::vector<std::uint64_t>;

// Frames first..first+n-1 of a picture that changes at every frame: frame f hashes to 1000 + f.
Hashes frames(int first, int n) {
  Hashes h;
  for (int f = first; f < first + n; ++f) h.push_back(1000u + static_cast<std::uint64_t>(f));
  return h;
}

TEST(CompatShift, EqualSequencesAreNotShifted) { EXPECT_EQ(compat_shift(frames(0, 60), frames(0, 60)), 0); }

// Run a is one frame ahead: its frame N shows b's frame N + 1.
TEST(CompatShift, ARunAheadHasAPositiveShift) { EXPECT_EQ(compat_shift(frames(1, 60), frames(0, 60)), 1); }

TEST(CompatShift, ARunBehindHasANegativeShift) { EXPECT_EQ(compat_shift(frames(0, 60), frames(3, 60)), -3); }

// A shift of 40 leaves 20 shared frames, less than half of a 60-frame tail: not accepted.
TEST(CompatShift, TooFewSharedFramesProveNothing) {
  EXPECT_EQ(compat_shift(frames(0, 60), frames(30, 60)), -30);
  EXPECT_EQ(compat_shift(frames(0, 60), frames(40, 60)), std::nullopt);
}

// Two different still pictures never match; one still picture matches at every shift, which
// proves nothing.
TEST(CompatShift, StillPicturesGiveNoShift) {
  EXPECT_EQ(compat_shift(Hashes(60, 7), Hashes(60, 8)), std::nullopt);
  EXPECT_EQ(compat_shift(Hashes(60, 7), Hashes(60, 7)), std::nullopt);
}

// One frame that differs in the shared part rules a shift out.
TEST(CompatShift, OneDifferentFrameRulesTheShiftOut) {
  Hashes a = frames(2, 60), b = frames(0, 60);
  a[30] = 5;
  EXPECT_NE(compat_shift(a, b), 2);
}

}  // namespace
