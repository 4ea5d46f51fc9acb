// SCPH-1080 digital pad protocol (psx-spx "Controllers - Communication Sequence").
#include "core/sio/pad.h"

namespace psx {

SioDevice::Reply DigitalPad::transfer(u8 command) {
  const u8 step = step_;
  if (step == kIgnoring) return {};
  ++step_;
  switch (step) {
    case 0:  // 01h controller access: the pad is selected and answers Hi-Z.
      return {0xFF, true};
    case 1:
      if (command != 0x42) {
        // Only the read command exists on this pad; anything else gets no /ACK, which ends the
        // transfer as far as the console is concerned.
        step_ = kIgnoring;
        return {};
      }
      switches_ = wire_switches(false);
      return {0x41, true};  // ID low byte: digital pad, one halfword follows
    case 2:
      return {0x5A, true};
    case 3:
      return {static_cast<u8>(switches_), true};
    case 4:
      return {static_cast<u8>(switches_ >> 8), false};  // last byte: no /ACK
    default:
      step_ = kIgnoring;
      return {};
  }
}

void DigitalPad::do_state(StateIO& s) {
  s.section("PADD", 1);
  s.pod(pressed_);
  s.pod(step_);
  s.pod(switches_);
  s.end_section("PADD");
}

}  // namespace psx
