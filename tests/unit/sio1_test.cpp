// SIO1 with nothing plugged in (psx-spx "Serial Interfaces (SIO)"): an idle line, registers that
// read back, a transmit that waits for CTS, reset, and the baud timer's countdown.
#include <gtest/gtest.h>

#include "core/sio/sio1.h"

namespace psx {
namespace {

TEST(Sio1, IdleLineWithoutCable) {
  Scheduler sched;
  Sio1 sio(sched);
  u32 stat = sio.io_read(0x4, 4);
  EXPECT_EQ(stat & 0x7FF, 0x5u);  // TX FIFO not full + TX idle; no RX data, DSR, CTS or IRQ
  EXPECT_EQ(sio.io_read(0x0, 1), 0u);
}

TEST(Sio1, TransmitWaitsForCtsUntilReset) {
  Scheduler sched;
  Sio1 sio(sched);
  sio.io_write(0x0, 0x55, 1);
  EXPECT_EQ(sio.io_read(0x4, 4) & 0x7, 0x4u);  // the byte waits: FIFO no longer "not full"
  sio.io_write(0xA, 0x40, 2);                   // SIO_CTRL.6: reset
  EXPECT_EQ(sio.io_read(0x4, 4) & 0x7, 0x5u);
}

TEST(Sio1, RegistersReadBack) {
  Scheduler sched;
  Sio1 sio(sched);
  sio.io_write(0x8, 0x004E, 2);  // MODE: MUL16, 8 bits, 1 stop bit
  sio.io_write(0xA, 0x0023, 2);  // CTRL: TXEN, DTR, RTS
  sio.io_write(0xE, 0x00DC, 2);  // BAUD
  EXPECT_EQ(sio.io_read(0x8, 2), 0x004Eu);
  EXPECT_EQ(sio.io_read(0xA, 2), 0x0023u);
  EXPECT_EQ(sio.io_read(0xE, 2), 0x00DCu);
  sio.io_write(0xA, 0x0033, 2);  // bit 4 (acknowledge) is an action, not stored
  EXPECT_EQ(sio.io_read(0xA, 2), 0x0023u);
}

TEST(Sio1, BaudTimerCountsDownFromBaudTimesFactorOverTwo) {
  Scheduler sched;
  Sio1 sio(sched);
  sio.io_write(0x8, 0x0002, 2);  // MUL16
  sio.io_write(0xE, 0x0088, 2);  // reload 88h * 16 / 2 = 1088 cycles
  sched.advance(100);
  EXPECT_EQ(sio.io_read(0x4, 4) >> 11, 1088u - 100u);
  sched.advance(1088);  // one whole period later: the same phase
  EXPECT_EQ(sio.io_read(0x4, 4) >> 11, 1088u - 100u);
}

}  // namespace
}  // namespace psx
