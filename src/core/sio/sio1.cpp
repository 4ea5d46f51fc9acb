// SIO1 register file with no cable attached.
#include "core/sio/sio1.h"

namespace psx {

u32 Sio1::io_read(u32 offset, u32 width) {
  u32 word = 0;
  switch (offset & ~3u) {
    case 0x0: break;  // SIO_RX_DATA: the FIFO is empty
    case 0x4:
      // SIO_STAT: bit 0 TX FIFO not full, bit 2 TX idle; DSR (7), CTS (8) and RX (1) stay off.
      word = (tx_pending_ ? 0u : 1u) | 1u << 2;
      word |= baud_timer_.stat_bits(baud_, mode_, sched_.now());
      break;
    case 0x8: word = mode_ | u32{ctrl_} << 16; break;
    case 0xC: word = misc_ | u32{baud_} << 16; break;
    default: break;
  }
  u32 mask = width >= 4 ? 0xFFFFFFFFu : (1u << (8 * width)) - 1;
  return (word >> (8 * (offset & 3))) & mask;
}

void Sio1::io_write(u32 offset, u32 value, u32 width) {
  // 32-bit writes to offset 8 and C also set the upper halfword's register.
  auto write_half = [&](u32 at, u16 v) {
    switch (at) {
      case 0x0: tx_pending_ = true; break;  // SIO_TX_DATA: queued until CTS
      case 0x8: mode_ = v & 0xFF; break;
      case 0xA:
        if (v & kCtrlReset) {
          mode_ = ctrl_ = misc_ = baud_ = 0;
          tx_pending_ = false;
          break;
        }
        ctrl_ = v & ~(kCtrlAcknowledge | kCtrlReset);
        break;
      case 0xC: misc_ = v; break;
      case 0xE:
        baud_ = v;
        baud_timer_.reload(sched_.now());
        break;
      default: break;  // SIO_STAT is read-only
    }
  };
  write_half(offset, static_cast<u16>(value));
  if (width == 4 && (offset == 0x8 || offset == 0xC)) write_half(offset + 2, static_cast<u16>(value >> 16));
}

void Sio1::do_state(StateIO& s) {
  s.section("SIO1", 1);
  s.pod(mode_), s.pod(ctrl_), s.pod(misc_), s.pod(baud_);
  baud_timer_.do_state(s);
  s.boolean(tx_pending_);
  s.end_section("SIO1");
}

}  // namespace psx
