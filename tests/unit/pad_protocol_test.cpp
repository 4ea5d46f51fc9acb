// Pad protocol byte sequences (psx-spx "Controllers - Communication Sequence", "Standard
// Digital/Analog Controllers", "Rumble Configuration") for the SCPH-1080 and the DualShock.
#include <gtest/gtest.h>

#include "core/sio/dualshock.h"
#include "core/sio/pad.h"
#include "sio_test_util.h"

namespace psx {
namespace {

using test::acks_but_last;
using test::command;
using V = std::vector<u8>;

// Start (bit 3) and Cross (bit 14) pressed: active-low halfword ~0x4008 = 0xBFF7.
constexpr u16 kStartCross = pad_button::kStart | pad_button::kCross;

TEST(PadDigital, ReadCommandRepliesId5A41AndActiveLowSwitches) {
  DigitalPad pad;
  pad.set_buttons(kStartCross);
  auto e = command(pad, {0x01, 0x42, 0x00, 0x00, 0x00});
  EXPECT_EQ(e.replies, (V{0xFF, 0x41, 0x5A, 0xF7, 0xBF}));
  EXPECT_EQ(e.acks, acks_but_last(5));
}

TEST(PadDigital, NoButtonsReadsAllOnes) {
  DigitalPad pad;
  auto e = command(pad, {0x01, 0x42, 0x00, 0x00, 0x00});
  EXPECT_EQ(e.replies, (V{0xFF, 0x41, 0x5A, 0xFF, 0xFF}));
}

TEST(PadDigital, HasNoL3R3) {
  DigitalPad pad;
  pad.set_buttons(pad_button::kL3 | pad_button::kR3 | pad_button::kSelect);
  auto e = command(pad, {0x01, 0x42, 0x00, 0x00, 0x00});
  EXPECT_EQ(e.replies[3], 0xFE);  // only Select (bit 0) low; L3/R3 bits read 1
}

TEST(PadDigital, OtherCommandsGetNoAck) {
  DigitalPad pad;
  auto e = command(pad, {0x01, 0x43, 0x00, 0x01, 0x00});
  EXPECT_EQ(e.replies, (V{0xFF, 0xFF, 0xFF, 0xFF, 0xFF}));
  EXPECT_EQ(e.acks, (std::vector<bool>{true, false, false, false, false}));
}

TEST(PadDigital, BytesAfterTheLastAreHiZ) {
  DigitalPad pad;
  auto e = command(pad, {0x01, 0x42, 0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(e.replies[5], 0xFF);
  EXPECT_FALSE(e.acks[5]);
}

TEST(PadDigital, DeselectRestartsTheSequence) {
  DigitalPad pad;
  test::clock_bytes(pad, {0x01, 0x42});
  auto e = command(pad, {0x01, 0x42, 0x00});
  EXPECT_EQ(e.replies, (V{0xFF, 0x41, 0x5A}));
}

// --- DualShock -------------------------------------------------------------------------------

const V kRead5 = {0x01, 0x42, 0x00, 0x00, 0x00};
const V kRead9 = {0x01, 0x42, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};

void enter_config(DualShock& pad) { command(pad, {0x01, 0x43, 0x00, 0x01, 0x00}); }
void exit_config(DualShock& pad) { command(pad, {0x01, 0x43, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}); }

TEST(PadDualShock, PowersUpInDigitalMode) {
  DualShock pad;
  pad.set_buttons(kStartCross);
  auto e = command(pad, kRead5);
  EXPECT_EQ(e.replies, (V{0xFF, 0x41, 0x5A, 0xF7, 0xBF}));
  EXPECT_EQ(e.acks, acks_but_last(5));
}

TEST(PadDualShock, AnalogButtonGivesId73AndSticks) {
  DualShock pad;
  pad.press_analog_button();
  pad.set_axes({0x10, 0x20, 0xE0, 0xF0});  // right x/y, left x/y
  pad.set_buttons(pad_button::kL3);         // bit 1: reported in analog mode
  auto e = command(pad, kRead9);
  EXPECT_EQ(e.replies, (V{0xFF, 0x73, 0x5A, 0xFD, 0xFF, 0x10, 0x20, 0xE0, 0xF0}));
  EXPECT_EQ(e.acks, acks_but_last(9));
  pad.press_analog_button();
  EXPECT_EQ(command(pad, kRead5).replies[1], 0x41);
}

TEST(PadDualShock, SticksCentreAt80h) {
  DualShock pad;
  pad.press_analog_button();
  auto e = command(pad, kRead9);
  EXPECT_EQ((V(e.replies.begin() + 5, e.replies.end())), (V{0x80, 0x80, 0x80, 0x80}));
}

TEST(PadDualShock, Command43InNormalModeRepliesLikeARead) {
  DualShock pad;
  pad.set_buttons(kStartCross);
  auto e = command(pad, {0x01, 0x43, 0x00, 0x01, 0x00});
  EXPECT_EQ(e.replies, (V{0xFF, 0x41, 0x5A, 0xF7, 0xBF}));
  EXPECT_TRUE(pad.config_mode());
}

TEST(PadDualShock, ConfigModeReadIsF3WithSticksEvenInDigitalMode) {
  DualShock pad;
  enter_config(pad);
  pad.set_axes({0x01, 0x02, 0x03, 0x04});
  auto e = command(pad, kRead9);
  EXPECT_EQ(e.replies, (V{0xFF, 0xF3, 0x5A, 0xFF, 0xFF, 0x01, 0x02, 0x03, 0x04}));
  EXPECT_EQ(e.acks, acks_but_last(9));
}

TEST(PadDualShock, ExitConfigRepliesZeros) {
  DualShock pad;
  enter_config(pad);
  auto e = command(pad, {0x01, 0x43, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(e.replies, (V{0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_FALSE(pad.config_mode());
  EXPECT_EQ(command(pad, kRead5).replies[1], 0x41);
}

TEST(PadDualShock, Command45ReportsLedState) {
  DualShock pad;
  enter_config(pad);
  const V get = {0x01, 0x45, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  EXPECT_EQ(command(pad, get).replies, (V{0xFF, 0xF3, 0x5A, 0x01, 0x02, 0x00, 0x02, 0x01, 0x00}));
  command(pad, {0x01, 0x44, 0x00, 0x01, 0x02, 0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(command(pad, get).replies, (V{0xFF, 0xF3, 0x5A, 0x01, 0x02, 0x01, 0x02, 0x01, 0x00}));
}

TEST(PadDualShock, Command44SetsAnalogModeAndLocksTheButton) {
  DualShock pad;
  enter_config(pad);
  auto e = command(pad, {0x01, 0x44, 0x00, 0x01, 0x03, 0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(e.replies, (V{0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}));
  exit_config(pad);
  EXPECT_TRUE(pad.analog_mode());
  EXPECT_EQ(command(pad, kRead9).replies[1], 0x73);
  pad.press_analog_button();  // locked: no effect
  EXPECT_TRUE(pad.analog_mode());
  enter_config(pad);
  command(pad, {0x01, 0x44, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x00});  // digital, unlocked
  exit_config(pad);
  EXPECT_FALSE(pad.analog_mode());
  pad.press_analog_button();
  EXPECT_TRUE(pad.analog_mode());
}

TEST(PadDualShock, Commands46And47And4CConstants) {
  DualShock pad;
  enter_config(pad);
  auto cmd = [&](u8 c, u8 xx) { return command(pad, {0x01, c, 0x00, xx, 0x00, 0x00, 0x00, 0x00, 0x00}).replies; };
  EXPECT_EQ(cmd(0x46, 0x00), (V{0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x01, 0x02, 0x00, 0x0A}));
  EXPECT_EQ(cmd(0x46, 0x01), (V{0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x01, 0x01, 0x01, 0x14}));
  EXPECT_EQ(cmd(0x46, 0x02), (V{0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(cmd(0x47, 0x00), (V{0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x02, 0x00, 0x01, 0x00}));
  EXPECT_EQ(cmd(0x48, 0x00), (V{0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00}));
  EXPECT_EQ(cmd(0x4C, 0x00), (V{0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00}));
  EXPECT_EQ(cmd(0x4C, 0x01), (V{0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x00, 0x07, 0x00, 0x00}));
  for (u8 c : {0x40, 0x41, 0x49, 0x4A, 0x4B, 0x4E, 0x4F})
    EXPECT_EQ(cmd(c, 0x00), (V{0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00})) << int(c);
}

TEST(PadDualShock, ConfigCommandsNeedConfigMode) {
  DualShock pad;
  auto e = command(pad, {0x01, 0x45, 0x00, 0x00, 0x00});
  EXPECT_EQ(e.replies, (V{0xFF, 0xFF, 0xFF, 0xFF, 0xFF}));
  EXPECT_EQ(e.acks, (std::vector<bool>{true, false, false, false, false}));
}

TEST(PadDualShock, Command4DRepliesOldMappingAndDrivesMotorsThrough42) {
  DualShock pad;
  enter_config(pad);
  pad.set_buttons(0);
  auto e = command(pad, {0x01, 0x4D, 0x00, 0x00, 0x01, 0xFF, 0xFF, 0xFF, 0xFF});
  EXPECT_EQ(e.replies, (V{0xFF, 0xF3, 0x5A, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF}));
  e = command(pad, {0x01, 0x4D, 0x00, 0x00, 0x01, 0xFF, 0xFF, 0xFF, 0xFF});
  EXPECT_EQ(e.replies, (V{0xFF, 0xF3, 0x5A, 0x00, 0x01, 0xFF, 0xFF, 0xFF, 0xFF}));
  exit_config(pad);
  // Default mapping: byte 3 bit 0 = small motor on/off, byte 4 = large motor speed.
  command(pad, {0x01, 0x42, 0x00, 0x01, 0xC0});
  EXPECT_EQ(pad.rumble().small, 0xFF);
  EXPECT_EQ(pad.rumble().large, 0xC0);
  command(pad, {0x01, 0x42, 0x00, 0x00, 0x00});
  EXPECT_EQ(pad.rumble().small, 0x00);
  EXPECT_EQ(pad.rumble().large, 0x00);
}

TEST(PadDualShock, Mapping4DUsesLastMatchingSlot) {
  DualShock pad;
  pad.press_analog_button();  // nine-byte reads, so bytes 5 and 6 exist
  enter_config(pad);
  // Final Fantasy VIII style (psx-spx): FFh 00h 01h ... -> small from byte 4, large from byte 5.
  command(pad, {0x01, 0x4D, 0x00, 0xFF, 0x00, 0x01, 0xFF, 0xFF, 0xFF});
  exit_config(pad);
  command(pad, {0x01, 0x42, 0x00, 0x01, 0x00, 0x77, 0x00, 0x00, 0x00});
  EXPECT_EQ(pad.rumble().small, 0x00);  // byte 3 is unmapped
  EXPECT_EQ(pad.rumble().large, 0x77);
  command(pad, {0x01, 0x42, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(pad.rumble().small, 0xFF);
  EXPECT_EQ(pad.rumble().large, 0x00);
}

TEST(PadDualShock, ConfigReadAlsoDrivesMotors) {
  DualShock pad;
  enter_config(pad);
  command(pad, {0x01, 0x4D, 0x00, 0x00, 0x01, 0xFF, 0xFF, 0xFF, 0xFF});
  command(pad, {0x01, 0x42, 0x00, 0x01, 0x55, 0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(pad.rumble().small, 0xFF);
  EXPECT_EQ(pad.rumble().large, 0x55);
}

TEST(PadDualShock, OldSingleMotorMethodUntilConfigMode) {
  DualShock pad;
  command(pad, {0x01, 0x42, 0x00, 0x40, 0x01});  // xx=40h..7Fh and odd yy: small motor on
  EXPECT_EQ(pad.rumble().small, 0xFF);
  EXPECT_EQ(pad.rumble().large, 0x00);
  command(pad, {0x01, 0x42, 0x00, 0x80, 0x01});  // xx bit 7 set: off
  EXPECT_EQ(pad.rumble().small, 0x00);
  command(pad, {0x01, 0x42, 0x00, 0x7F, 0xFF});
  EXPECT_EQ(pad.rumble().small, 0xFF);
  command(pad, {0x01, 0x42, 0x00, 0x40, 0x02});  // even yy: off
  EXPECT_EQ(pad.rumble().small, 0x00);
  enter_config(pad);
  exit_config(pad);
  command(pad, {0x01, 0x42, 0x00, 0x40, 0x01});  // old method now disabled, mapping all FFh
  EXPECT_EQ(pad.rumble().small, 0x00);
}

TEST(PadDualShock, AnalogButtonStopsMotorsAndClearsMapping) {
  DualShock pad;
  enter_config(pad);
  command(pad, {0x01, 0x4D, 0x00, 0x00, 0x01, 0xFF, 0xFF, 0xFF, 0xFF});
  exit_config(pad);
  command(pad, {0x01, 0x42, 0x00, 0x01, 0x90});
  ASSERT_EQ(pad.rumble().large, 0x90);
  pad.press_analog_button();
  EXPECT_EQ(pad.rumble().small, 0x00);
  EXPECT_EQ(pad.rumble().large, 0x00);
  command(pad, {0x01, 0x42, 0x00, 0x01, 0x90, 0x00, 0x00, 0x00, 0x00});
  EXPECT_EQ(pad.rumble().large, 0x00);
}

TEST(PadDualShock, SaveStateMidCommandContinuesIdentically) {
  DualShock a;
  a.press_analog_button();
  a.set_buttons(kStartCross);
  test::clock_bytes(a, {0x01, 0x42, 0x00});
  StateIO w;
  a.do_state(w);
  DualShock b;
  StateIO r(w.buffer().data(), w.buffer().size());
  b.do_state(r);
  EXPECT_TRUE(r.at_end());
  const V rest = {0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  EXPECT_EQ(test::clock_bytes(b, rest).replies, test::clock_bytes(a, rest).replies);
  EXPECT_EQ(b.buttons(), kStartCross);
}

}  // namespace
}  // namespace psx
