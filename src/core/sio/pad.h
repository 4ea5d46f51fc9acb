// Controllers on the SIO0 controller ports (psx-spx "Controllers - Communication Sequence",
// "Controllers - Standard Digital/Analog Controllers"): the host-facing input state shared by
// every pad type, and the SCPH-1080 digital pad. The DualShock lives in dualshock.h.
#pragma once
#include "core/sio/sio_device.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

// The 16 switches in psx-spx order (halfword 1 of the read reply). The host API uses 1 = pressed;
// on the wire the bits are active-low (0 = pressed).
namespace pad_button {
inline constexpr u16 kSelect = 1u << 0;
inline constexpr u16 kL3 = 1u << 1;
inline constexpr u16 kR3 = 1u << 2;
inline constexpr u16 kStart = 1u << 3;
inline constexpr u16 kUp = 1u << 4;
inline constexpr u16 kRight = 1u << 5;
inline constexpr u16 kDown = 1u << 6;
inline constexpr u16 kLeft = 1u << 7;
inline constexpr u16 kL2 = 1u << 8;
inline constexpr u16 kR2 = 1u << 9;
inline constexpr u16 kL1 = 1u << 10;
inline constexpr u16 kR1 = 1u << 11;
inline constexpr u16 kTriangle = 1u << 12;
inline constexpr u16 kCircle = 1u << 13;
inline constexpr u16 kCross = 1u << 14;
inline constexpr u16 kSquare = 1u << 15;
}  // namespace pad_button

// Stick positions as the pad reports them: 00h = left/up, 80h = centre, FFh = right/down.
struct AnalogAxes {
  u8 right_x = 0x80;
  u8 right_y = 0x80;
  u8 left_x = 0x80;
  u8 left_y = 0x80;
};

// Current rumble motor drive: the small (right) motor is on/off (0 or 255), the large (left)
// motor's speed is 0..255 (psx-spx "Controllers - Rumble Configuration").
struct Rumble {
  u8 small = 0;
  u8 large = 0;
};

class Pad : public SioDevice {
 public:
  enum class Kind : u8 { Digital = 1, DualShock = 2 };

  virtual Kind kind() const = 0;
  // Host input, set between emulation steps. `pressed` uses the pad_button bits.
  void set_buttons(u16 pressed) { pressed_ = pressed; }
  u16 buttons() const { return pressed_; }
  virtual void set_axes(const AnalogAxes& axes) = 0;
  virtual Rumble rumble() const = 0;
  virtual void do_state(StateIO& s) = 0;

  // psx-spx gives no figure for pads; 338 cycles (10 us) is well inside the console's 100 us
  // "no device" timeout and later than the ~100 cycles after which the kernel acknowledges the
  // previous IRQ7 (psx-spx "Emulation Note").
  static constexpr Cycles kAckDelay = 338;
  Cycles ack_delay() const override { return kAckDelay; }

 protected:
  // Switch halfword as sent on the wire (active-low). L3/R3 exist only while the sticks are
  // enabled; otherwise their bits read 1 ("Released/None/Disabled").
  u16 wire_switches(bool sticks_enabled) const {
    u16 pressed = pressed_;
    if (!sticks_enabled) pressed &= static_cast<u16>(~(pad_button::kL3 | pad_button::kR3));
    return static_cast<u16>(~pressed);
  }

  u16 pressed_ = 0;
};

// SCPH-1080 digital pad: answers only the read command 42h with ID 5A41h and two switch bytes.
class DigitalPad final : public Pad {
 public:
  Kind kind() const override { return Kind::Digital; }
  // The SCPH-1080 has no sticks and no motors.
  void set_axes(const AnalogAxes&) override {}
  Rumble rumble() const override { return {}; }

  Reply transfer(u8 command) override;
  void deselect() override { step_ = 0; }
  void do_state(StateIO& s) override;

 private:
  static constexpr u8 kIgnoring = 0xFF;  // step_ value after an unsupported command

  u8 step_ = 0;        // index of the next byte within the current selection
  u16 switches_ = 0;   // wire switch halfword latched when the read command arrived
};

}  // namespace psx
