// Console controller input: buttons, timed presses, analog sticks and rumble, forwarded to the
// pads on SIO0.
#include <stdexcept>

#include "core/console.h"
#include "core/sio/dualshock.h"

namespace psx {

int Console::port_index(int port) {
  if (port != 1 && port != 2) throw std::invalid_argument("controller port must be 1 or 2, not " + std::to_string(port));
  return port - 1;
}

void Console::plug_pad(int port, PadType type) {
  ThreadOwner::Use use(owner_);
  int i = port_index(port);
  std::unique_ptr<Pad> pad;
  if (type == PadType::Digital) pad = std::make_unique<DigitalPad>();
  if (type == PadType::DualShock) pad = std::make_unique<DualShock>();
  sio0_.attach_pad(i, std::move(pad));
  hold_frames_[i] = {};
}

void Console::insert_memory_card(int port, const std::string& path) {
  ThreadOwner::Use use(owner_);
  int i = port_index(port);
  try {
    sio0_.attach_memory_card(i, std::make_unique<MemoryCard>(path));
  } catch (const MemoryCardError& e) {
    throw InputError(e.what());
  }
}

void Console::set_buttons(int port, u16 pressed) {
  ThreadOwner::Use use(owner_);
  int i = port_index(port);
  sio0_.set_buttons(i, pressed);
  for (u32 b = 0; b < 16; ++b)
    if (!(pressed >> b & 1)) hold_frames_[i][b] = 0;
}

void Console::press(int port, u16 buttons) {
  ThreadOwner::Use use(owner_);
  int i = port_index(port);
  if (Pad* pad = sio0_.pad(i)) sio0_.set_buttons(i, pad->buttons() | buttons);
}

void Console::release(int port, u16 buttons) {
  ThreadOwner::Use use(owner_);
  int i = port_index(port);
  if (Pad* pad = sio0_.pad(i)) sio0_.set_buttons(i, pad->buttons() & ~buttons);
  for (u32 b = 0; b < 16; ++b)
    if (buttons >> b & 1) hold_frames_[i][b] = 0;
}

void Console::press_for(int port, u16 buttons, u32 frames) {
  ThreadOwner::Use use(owner_);
  press(port, buttons);
  int i = port_index(port);
  for (u32 b = 0; b < 16; ++b)
    if (buttons >> b & 1) hold_frames_[i][b] = frames;
}

void Console::release_timed_buttons() {
  for (int i = 0; i < 2; ++i) {
    u16 done = 0;
    for (u32 b = 0; b < 16; ++b)
      if (hold_frames_[i][b] && --hold_frames_[i][b] == 0) done |= u16(1u << b);
    if (done)
      if (Pad* pad = sio0_.pad(i)) sio0_.set_buttons(i, pad->buttons() & ~done);
  }
}

void Console::set_axes(int port, const AnalogAxes& axes) { sio0_.set_axes(port_index(port), axes); }

Rumble Console::rumble(int port) const { return sio0_.rumble(port_index(port)); }

}  // namespace psx
