// `psxrl run --input` scripts (src/cli/input_script.h): FRAME BUTTONS [HOLD_FRAMES] lines, '+'
// joined button names mapped to psx-spx's pad switch bits, comments, and errors naming name:line.
#include <gtest/gtest.h>

#include "cli/input_script.h"
#include "core/input_error.h"
#include "core/sio/pad.h"

namespace {

using psxrl::cli::parse_input_script;

std::string error_of(const std::string& text) {
  try {
    parse_input_script(text, "s.txt");
  } catch (const psx::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CliInputScript, PressesHoldsAndComments) {
  auto p = parse_input_script("# demo\n\n  10 up   # roll\n10 cross+up 3\n40 l1+r2+select+start 1\n", "s.txt");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].frame, 10u);
  EXPECT_EQ(p[0].buttons, 1u << 4);  // psx-spx: Up is bit 4 of the switch halfword
  EXPECT_EQ(p[0].hold, 1u);          // default hold
  EXPECT_EQ(p[1].buttons, (1u << 14) | (1u << 4));  // Cross bit 14
  EXPECT_EQ(p[1].hold, 3u);
  EXPECT_EQ(p[2].frame, 40u);
  EXPECT_EQ(p[2].buttons, (1u << 10) | (1u << 9) | (1u << 0) | (1u << 3));  // L1 10, R2 9, Select 0, Start 3
}

TEST(CliInputScript, EveryButtonName) {
  auto p = parse_input_script(
      "0 up+down+left+right+cross+circle+square+triangle+l1+l2+r1+r2+start+select+l3+r3\n", "s.txt");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].buttons, 0xFFFFu);  // all 16 switches
}

TEST(CliInputScript, DefectsNameFileLineAndWhatWasExpected) {
  EXPECT_EQ(error_of("x up\n"), "s.txt:1: expected a frame number, found 'x'");
  EXPECT_EQ(error_of("# c\n5\n"), "s.txt:2: expected buttons after the frame number (e.g. up+cross)");
  EXPECT_NE(error_of("5 up+\n").find("s.txt:1: expected a button name"), std::string::npos);
  EXPECT_NE(error_of("5 UP\n").find("found 'UP'"), std::string::npos);
  EXPECT_EQ(error_of("5 up 0\n"), "s.txt:1: expected a hold time of 1 to 1000000 frames, found '0'");
  EXPECT_EQ(error_of("5 up 2 x\n"), "s.txt:1: expected the end of the line after FRAME BUTTONS [HOLD_FRAMES], found 'x'");
  EXPECT_EQ(error_of("9 up\n8 up\n"), "s.txt:2: expected a frame number not below the previous line's 9, found 8");
  EXPECT_EQ(error_of("-1 up\n"), "s.txt:1: expected a frame number, found '-1'");
}

}  // namespace
