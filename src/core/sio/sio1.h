// SIO1: the serial port on the back of the console (psx-spx "Serial Interfaces (SIO)",
// 1F801050h-1F80105Fh), with nothing plugged in. The registers hold what programs write, the
// status shows the baud timer and an idle line: no DSR, no CTS, nothing received. A byte written
// to SIO_TX_DATA waits forever (transmission needs CTS), so "TX FIFO not full" drops until a
// reset. The BIOS and games probe this port at start-up; a link cable is not emulated.
#pragma once
#include "core/io_device.h"
#include "core/scheduler.h"
#include "core/sio/baud_timer.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

class Sio1 final : public IoDevice {
 public:
  static constexpr u32 kBase = 0x1F801050;
  static constexpr u32 kSize = 16;

  explicit Sio1(Scheduler& sched) : sched_(sched) {}

  u32 io_read(u32 offset, u32 width) override;
  void io_write(u32 offset, u32 value, u32 width) override;

  void do_state(StateIO& s);

 private:
  // SIO_CTRL bits (write-only actions).
  static constexpr u16 kCtrlAcknowledge = 1u << 4;
  static constexpr u16 kCtrlReset = 1u << 6;

  Scheduler& sched_;
  u16 mode_ = 0, ctrl_ = 0, misc_ = 0, baud_ = 0;
  BaudTimer baud_timer_;  // reloaded when SIO_BAUD is written
  bool tx_pending_ = false;  // a byte waits for CTS, which never comes
};

}  // namespace psx
