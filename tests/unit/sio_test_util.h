// Helpers shared by the SIO0 / pad / memory card unit tests: clock a byte sequence through a
// device and compare replies and /ACKs with the sequences tabulated in psx-spx.
#pragma once
#include <vector>

#include "core/sio/sio_device.h"

namespace psx::test {

struct Exchange {
  std::vector<u8> replies;
  std::vector<bool> acks;
};

// Sends `commands` in one selection (without deselecting before or after).
inline Exchange clock_bytes(SioDevice& dev, const std::vector<u8>& commands) {
  Exchange e;
  for (u8 c : commands) {
    const SioDevice::Reply r = dev.transfer(c);
    e.replies.push_back(r.data);
    e.acks.push_back(r.ack);
  }
  return e;
}

// A whole command: select (deselect first), send, deselect.
inline Exchange command(SioDevice& dev, const std::vector<u8>& commands) {
  dev.deselect();
  Exchange e = clock_bytes(dev, commands);
  dev.deselect();
  return e;
}

// /ACK after every byte but the last (psx-spx: "no need Acknowledge at last data").
inline std::vector<bool> acks_but_last(size_t n) {
  std::vector<bool> v(n, true);
  v.back() = false;
  return v;
}

}  // namespace psx::test
