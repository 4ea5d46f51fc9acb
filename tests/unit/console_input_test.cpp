// Console input API (issue 8): buttons per port, timed presses released at frame ends.
#include <gtest/gtest.h>

#include "core/console.h"

namespace psx {
namespace {

TEST(ConsoleInput, PressReleaseAndSet) {
  Console c;
  c.press(1, pad_button::kCross);
  c.press(1, pad_button::kUp);
  EXPECT_EQ(c.sio0().pad(0)->buttons(), pad_button::kCross | pad_button::kUp);
  c.release(1, pad_button::kCross);
  EXPECT_EQ(c.sio0().pad(0)->buttons(), pad_button::kUp);
  c.set_buttons(1, pad_button::kStart);
  EXPECT_EQ(c.sio0().pad(0)->buttons(), pad_button::kStart);
  EXPECT_THROW(c.press(3, pad_button::kStart), std::invalid_argument);
  c.press(2, pad_button::kStart);  // port 2 is empty by default: nothing happens
  EXPECT_EQ(c.sio0().pad(1), nullptr);
}

TEST(ConsoleInput, PressForHoldsExactlyNFrames) {
  Console c;
  c.boot_exe(PSXRL_BUILD_DIR "/bench/cpu_loop.exe");
  c.press_for(1, pad_button::kCross | pad_button::kLeft, 3);
  c.press_for(1, pad_button::kCircle, 1);
  c.run_frames(1);
  EXPECT_EQ(c.sio0().pad(0)->buttons(), pad_button::kCross | pad_button::kLeft);
  c.run_frames(1);
  EXPECT_EQ(c.sio0().pad(0)->buttons(), pad_button::kCross | pad_button::kLeft);
  c.run_frames(1);
  EXPECT_EQ(c.sio0().pad(0)->buttons(), 0);
}

TEST(ConsoleInput, TimedPressesSurviveSaveStates) {
  Console a;
  a.boot_exe(PSXRL_BUILD_DIR "/bench/cpu_loop.exe");
  a.press_for(1, pad_button::kTriangle, 2);
  auto blob = a.save_state();
  Console b;
  b.boot_exe(PSXRL_BUILD_DIR "/bench/cpu_loop.exe");
  b.load_state(blob);
  EXPECT_EQ(b.sio0().pad(0)->buttons(), pad_button::kTriangle);
  b.run_frames(2);
  EXPECT_EQ(b.sio0().pad(0)->buttons(), 0);
}

}  // namespace
}  // namespace psx
