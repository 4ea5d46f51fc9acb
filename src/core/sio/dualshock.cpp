// DualShock (SCPH-1200) command handling: normal-mode read 42h/43h, config-mode commands 40h-4Fh,
// mode switching and rumble (psx-spx "Controllers - Rumble Configuration").
#include "core/sio/dualshock.h"

namespace psx {

namespace {
constexpr u8 kIdDigital = 0x41;  // 5A41h: digital mode, one halfword follows
constexpr u8 kIdAnalog = 0x73;   // 5A73h: analog (LED red) mode, three halfwords follow
constexpr u8 kIdConfig = 0xF3;   // 5AF3h: config mode, always three halfwords
}  // namespace

DualShock::DualShock() { rumble_config_.fill(0xFF); }

void DualShock::press_analog_button() {
  if (analog_locked_) return;
  analog_mode_ = !analog_mode_;
  reset_rumble();
}

// 44h and the Analog button reset the mapping to all FFh, so no parameter byte drives a motor;
// the motors stop rather than keep running with nothing able to stop them.
void DualShock::reset_rumble() {
  rumble_config_.fill(0xFF);
  motor_small_ = 0;
  motor_large_ = 0;
}

SioDevice::Reply DualShock::transfer(u8 command) {
  const u8 step = step_;
  if (step == kIgnoring) return {};
  ++step_;
  if (step == 0) return {0xFF, true};  // 01h controller access, Hi-Z reply
  if (step == 1) {
    if (!begin_command(command)) {
      step_ = kIgnoring;  // unknown command: no /ACK, the console sees the transfer end
      return {};
    }
    return {reply_[1], true};
  }
  if (step >= reply_len_) {
    step_ = kIgnoring;
    return {};
  }
  Reply r{reply_[step], static_cast<u8>(step + 1) < reply_len_};
  take_parameter(step, command);
  return r;
}

bool DualShock::begin_command(u8 command) {
  command_ = command;
  held_param_ = 0;
  reply_.fill(0x00);
  reply_[0] = 0xFF;
  reply_[2] = 0x5A;
  if (!config_mode_) {
    if (command != 0x42 && command != 0x43) return false;
    begin_normal_read();
    return true;
  }
  if (command < 0x40 || command > 0x4F) return false;
  begin_config_reply(command);
  return true;
}

// 42h/43h in normal mode: ID, 5Ah, switches, and the sticks only in analog mode.
void DualShock::begin_normal_read() {
  const u16 sw = wire_switches(analog_mode_);
  reply_[1] = analog_mode_ ? kIdAnalog : kIdDigital;
  reply_[3] = static_cast<u8>(sw);
  reply_[4] = static_cast<u8>(sw >> 8);
  reply_len_ = 5;
  if (!analog_mode_) return;
  reply_[5] = axes_.right_x;
  reply_[6] = axes_.right_y;
  reply_[7] = axes_.left_x;
  reply_[8] = axes_.left_y;
  reply_len_ = 9;
}

// Config mode: ID F3h and always nine bytes. Replies that depend on a parameter byte (46h, 4Ch)
// are completed in take_parameter once that byte has arrived.
void DualShock::begin_config_reply(u8 command) {
  reply_[1] = kIdConfig;
  reply_len_ = kReplyMax;
  switch (command) {
    case 0x42: {  // read with the sticks forced on, even in digital mode
      const u16 sw = wire_switches(true);
      reply_[3] = static_cast<u8>(sw);
      reply_[4] = static_cast<u8>(sw >> 8);
      reply_[5] = axes_.right_x;
      reply_[6] = axes_.right_y;
      reply_[7] = axes_.left_x;
      reply_[8] = axes_.left_y;
      break;
    }
    case 0x45:  // LED state and constants: 01h 02h led 02h 01h 00h
      reply_[3] = 0x01;
      reply_[4] = 0x02;
      reply_[5] = analog_mode_ ? 0x01 : 0x00;
      reply_[6] = 0x02;
      reply_[7] = 0x01;
      break;
    case 0x47:  // constants 00h 00h 02h 00h 01h 00h
      reply_[5] = 0x02;
      reply_[7] = 0x01;
      break;
    case 0x48:  // constants 00h 00h 00h 00h 01h 00h
      reply_[7] = 0x01;
      break;
    case 0x4D:  // replies with the mapping being replaced
      for (u8 i = 0; i < rumble_config_.size(); ++i) reply_[3 + i] = rumble_config_[i];
      break;
    default:  // 40h 41h 43h 44h 46h 49h-4Ch 4Eh 4Fh: zeros (46h/4Ch filled in later)
      break;
  }
}

void DualShock::take_parameter(u8 step, u8 value) {
  switch (command_) {
    case 0x42:
      if (step >= 3) take_motor_byte(static_cast<u8>(step - 3), value);
      break;
    case 0x43:
      // 00h = normal mode, 01h = config mode. Applied as soon as the byte arrives; psx-spx notes
      // some pads wait for the whole command, so games do not rely on either.
      if (step != 3) break;
      if (value == 0x01) {
        config_mode_ = true;
        legacy_rumble_ = false;  // the old method stays off until a power cycle
      } else if (value == 0x00) {
        config_mode_ = false;
      }
      break;
    case 0x44:
      // "44h 00h val sel": val 00h = digital, 01h = analog. psx-spx applies val when sel=02h;
      // games also send sel=03h, which additionally locks the Analog button.
      if (step == 3) held_param_ = value;
      if (step == 4) {
        if (held_param_ <= 0x01) analog_mode_ = held_param_ == 0x01;
        analog_locked_ = value == 0x03;
        reset_rumble();
      }
      break;
    case 0x46:  // variable response A, selected by the parameter byte
      if (step == 3 && value <= 0x01) {
        static constexpr u8 kResponse[2][4] = {{0x01, 0x02, 0x00, 0x0A}, {0x01, 0x01, 0x01, 0x14}};
        for (u8 i = 0; i < 4; ++i) reply_[5 + i] = kResponse[value][i];
      }
      break;
    case 0x4C:  // variable response B
      if (step == 3) reply_[6] = value == 0x00 ? 0x04 : value == 0x01 ? 0x07 : 0x00;
      break;
    case 0x4D:  // mapping bytes follow the command and the 00h (TAP) byte at step 2
      if (step < 3 || step - 3u >= rumble_config_.size()) break;
      rumble_config_[step - 3] = value;
      if (motor_slot(0x00) == kNoMotorSlot) motor_small_ = 0;
      if (motor_slot(0x01) == kNoMotorSlot) motor_large_ = 0;
      break;
    default:
      break;
  }
}

// Slot of the last mapping entry equal to `code` (psx-spx: the last 00h/01h byte wins).
u8 DualShock::motor_slot(u8 code) const {
  u8 slot = kNoMotorSlot;
  for (u8 i = 0; i < rumble_config_.size(); ++i)
    if (rumble_config_[i] == code) slot = i;
  return slot;
}

void DualShock::take_motor_byte(u8 slot, u8 value) {
  if (legacy_rumble_) {
    // Old method: small motor on while xx = 40h..7Fh (bit7=0, bit6=1) and yy is odd.
    if (slot == 0) held_param_ = value;
    if (slot == 1) motor_small_ = ((held_param_ & 0xC0) == 0x40 && (value & 0x01)) ? 0xFF : 0x00;
    return;
  }
  if (slot == motor_slot(0x00)) motor_small_ = (value & 0x01) ? 0xFF : 0x00;  // on/off
  if (slot == motor_slot(0x01)) motor_large_ = value;                         // speed
}

void DualShock::do_state(StateIO& s) {
  s.section("DSHK", 1);
  s.pod(pressed_);
  s.pod(axes_);
  s.boolean(analog_mode_);
  s.boolean(analog_locked_);
  s.boolean(config_mode_);
  s.boolean(legacy_rumble_);
  s.pod(rumble_config_);
  s.pod(motor_small_);
  s.pod(motor_large_);
  s.pod(step_);
  s.pod(command_);
  s.pod(reply_len_);
  s.pod(reply_);
  s.pod(held_param_);
  if (s.loading() && reply_len_ > kReplyMax) s.fail("DualShock reply length out of range");
  s.end_section("DSHK");
}

}  // namespace psx
