// SCPH-1200 DualShock analog pad (psx-spx "Controllers - Standard Digital/Analog Controllers" and
// "Controllers - Rumble Configuration"): digital/analog mode with the Analog button, the two
// sticks, config mode (commands 40h-4Fh) and the two rumble motors, driven either by the old
// single-motor method or by the 4Dh motor mapping.
#pragma once
#include <array>

#include "core/sio/pad.h"

namespace psx {

class DualShock final : public Pad {
 public:
  DualShock();

  Kind kind() const override { return Kind::DualShock; }
  void set_axes(const AnalogAxes& axes) override { axes_ = axes; }
  const AnalogAxes& axes() const { return axes_; }
  Rumble rumble() const override { return {motor_small_, motor_large_}; }

  // The Analog button: toggles digital/analog mode unless a game locked it (command 44h). Like
  // the real pad it also stops the motors and clears the motor mapping.
  void press_analog_button();
  bool analog_mode() const { return analog_mode_; }
  bool config_mode() const { return config_mode_; }

  Reply transfer(u8 command) override;
  void deselect() override { step_ = 0; }
  void do_state(StateIO& s) override;

 private:
  static constexpr u8 kIgnoring = 0xFF;  // step_ value after an unsupported command
  static constexpr u8 kReplyMax = 9;     // longest DualShock transfer, address byte included
  static constexpr u8 kNoMotorSlot = 0xFF;

  bool begin_command(u8 command);
  void begin_normal_read();
  void begin_config_reply(u8 command);
  void take_parameter(u8 step, u8 value);
  void take_motor_byte(u8 slot, u8 value);
  void reset_rumble();
  u8 motor_slot(u8 code) const;

  AnalogAxes axes_;
  bool analog_mode_ = false;    // LED on: ID 73h, sticks and L3/R3 reported
  bool analog_locked_ = false;  // 44h with sel=03h disables the Analog button
  bool config_mode_ = false;    // ID F3h, commands 40h-4Fh accepted
  // The old method (42h bytes 40h..7Fh / odd) works until config mode is first entered.
  bool legacy_rumble_ = true;
  // 4Dh mapping of 42h parameter bytes 3..8: 00h = small motor, 01h = large motor, FFh = none.
  std::array<u8, 6> rumble_config_{};
  u8 motor_small_ = 0;
  u8 motor_large_ = 0;

  // Current transfer.
  u8 step_ = 0;     // index of the next byte within the selection (0 = address byte 01h)
  u8 command_ = 0;  // command byte (index 1)
  u8 reply_len_ = 0;
  std::array<u8, kReplyMax> reply_{};
  u8 held_param_ = 0;  // parameter byte kept for the next one (42h old-method xx, 44h val)
};

}  // namespace psx
