// A device on the SIO0 serial bus behind a /JOYn select line: a controller or a memory card
// (psx-spx "Controller and Memory Card Misc"). While its slot is selected the console clocks one
// byte out on JOYCMD and, in the same eight clocks, one byte in on JOYDAT; after each byte except
// the last of a command the device pulls /ACK low to ask for the next one.
#pragma once
#include "core/types.h"

namespace psx {

class SioDevice {
 public:
  struct Reply {
    u8 data = 0xFF;    // byte shifted back to the console (0xFF = the line floats high, Hi-Z)
    bool ack = false;  // whether /ACK is pulsed after this byte ("more data" request)
  };

  virtual ~SioDevice() = default;
  // One byte exchange while selected. The reply byte was prepared from earlier bytes: a serial
  // device cannot answer a byte with something that depends on that same byte.
  virtual Reply transfer(u8 command) = 0;
  // Cycles from the end of the byte just transferred to the falling edge of /ACK.
  virtual Cycles ack_delay() const = 0;
  // /JOYn went high: the device abandons the current command and waits for a new address byte.
  virtual void deselect() = 0;
};

}  // namespace psx
