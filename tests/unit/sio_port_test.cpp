// SIO0 register interface (psx-spx "Controller and Memory Card I/O Ports"): transfer timing from
// JOY_BAUD, /ACK and IRQ7, slot selection, RX FIFO, JOY_CTRL acknowledge/reset, save states, and
// the Console wiring at 1F801040h.
#include <gtest/gtest.h>

#include <memory>

#include "core/console.h"
#include "core/sio/dualshock.h"
#include "core/sio/sio0.h"

namespace psx {
namespace {

constexpr u32 kData = 0x0, kStat = 0x4, kMode = 0x8, kCtrl = 0xA, kBaud = 0xE;
constexpr u32 kStatTxReady1 = 1u << 0, kStatRxNotEmpty = 1u << 1, kStatTxReady2 = 1u << 2;
constexpr u32 kStatAckLow = 1u << 7, kStatIrq = 1u << 9;
constexpr u32 kIStatPad = 1u << 7;
// Usual BIOS setup: JOY_MODE 000Dh (8 bit, MUL1), JOY_BAUD 0088h, JOY_CTRL 1003h (TXEN, /JOY1
// low, ACK interrupt) or 3003h for slot 2.
constexpr u16 kCtrlSlot1 = 0x1003, kCtrlSlot2 = 0x3003;
// One byte at Reload 88h, MUL1: 8 bits of 88h cycles (44h low + 44h high) = 1088 cycles.
constexpr Cycles kByte = 8 * 0x88;

struct Rig {
  Scheduler sched;
  InterruptController irq;
  Sio0 sio{sched, irq};

  Rig() {
    sio.io_write(kCtrl, 0x40, 2);  // reset
    sio.io_write(kMode, 0x000D, 2);
    sio.io_write(kBaud, 0x0088, 2);
  }
  void run_for(Cycles n) {
    const Cycles end = sched.now() + n;
    while (sched.next_deadline() <= end) {
      sched.advance(sched.next_deadline() - sched.now());
      sched.run_due_events();
    }
    sched.advance(end - sched.now());
  }
  u32 stat() { return sio.io_read(kStat, 4) & 0x7FF; }
  void ack_irq() {
    sio.io_write(kCtrl, sio.io_read(kCtrl, 2) | 0x10, 2);
    irq.write(0, ~kIStatPad);  // I_STAT bits are acknowledged by writing 0
  }
  // Sends one byte, waits up to 3000 cycles for IRQ7, returns the reply byte; `acked` says
  // whether IRQ7 came.
  u8 send(u8 b, bool& acked) {
    ack_irq();
    sio.io_write(kData, b, 1);
    acked = false;
    for (int i = 0; i < 3000 && !acked; ++i) {
      run_for(1);
      acked = irq.stat() & kIStatPad;
    }
    if (!acked) run_for(1);
    return static_cast<u8>(sio.io_read(kData, 1));
  }
};

TEST(SioPort, IdleStatusAfterReset) {
  Rig r;
  EXPECT_EQ(r.stat(), kStatTxReady1 | kStatTxReady2);
  EXPECT_EQ(r.sio.io_read(kMode, 2), 0x000Du);
  EXPECT_EQ(r.sio.io_read(kBaud, 2), 0x0088u);
}

TEST(SioPort, ByteTakesBaudTimesEightCycles) {
  Rig r;
  r.sio.io_write(kCtrl, kCtrlSlot1, 2);
  r.sio.io_write(kData, 0x01, 1);
  EXPECT_EQ(r.stat() & (kStatTxReady2 | kStatRxNotEmpty), 0u);
  EXPECT_TRUE(r.stat() & kStatTxReady1);  // the byte went straight into the shift register
  r.run_for(kByte - 1);
  EXPECT_EQ(r.stat() & (kStatTxReady2 | kStatRxNotEmpty), 0u);
  r.run_for(1);
  EXPECT_EQ(r.stat() & (kStatTxReady2 | kStatRxNotEmpty), kStatTxReady2 | kStatRxNotEmpty);
  EXPECT_EQ(r.sio.io_read(kData, 1), 0xFFu);  // Hi-Z answer to the address byte
  EXPECT_EQ(r.stat() & kStatRxNotEmpty, 0u);
}

TEST(SioPort, Mul16FactorSlowsTheByte) {
  Rig r;
  r.sio.io_write(kMode, 0x000E, 2);  // factor 2 = MUL16
  r.sio.io_write(kCtrl, kCtrlSlot1, 2);
  r.sio.io_write(kData, 0x01, 1);
  r.run_for(16 * kByte - 1);
  EXPECT_EQ(r.stat() & kStatRxNotEmpty, 0u);
  r.run_for(1);
  EXPECT_NE(r.stat() & kStatRxNotEmpty, 0u);
}

TEST(SioPort, AckPulseRaisesIrq7AfterTheDeviceDelay) {
  Rig r;
  r.sio.attach_pad(0, std::make_unique<DigitalPad>());
  r.sio.io_write(kCtrl, kCtrlSlot1, 2);
  r.sio.io_write(kData, 0x01, 1);
  r.run_for(kByte + Pad::kAckDelay - 1);
  EXPECT_EQ(r.irq.stat() & kIStatPad, 0u);
  EXPECT_EQ(r.stat() & (kStatAckLow | kStatIrq), 0u);
  r.run_for(1);
  EXPECT_EQ(r.irq.stat() & kIStatPad, kIStatPad);
  EXPECT_EQ(r.stat() & (kStatAckLow | kStatIrq), kStatAckLow | kStatIrq);
  r.run_for(Sio0::kAckPulse - 1);
  EXPECT_TRUE(r.stat() & kStatAckLow);
  r.run_for(1);
  EXPECT_EQ(r.stat() & kStatAckLow, 0u);
  EXPECT_TRUE(r.stat() & kStatIrq);  // sticky until acknowledged
  r.sio.io_write(kCtrl, kCtrlSlot1 | 0x10, 2);
  EXPECT_EQ(r.stat() & kStatIrq, 0u);
}

TEST(SioPort, AckWithoutAckInterruptEnableRaisesNoIrq) {
  Rig r;
  r.sio.attach_pad(0, std::make_unique<DigitalPad>());
  r.sio.io_write(kCtrl, 0x0003, 2);
  r.sio.io_write(kData, 0x01, 1);
  r.run_for(kByte + Pad::kAckDelay);
  EXPECT_TRUE(r.stat() & kStatAckLow);
  EXPECT_EQ(r.stat() & kStatIrq, 0u);
  EXPECT_EQ(r.irq.stat(), 0u);
}

TEST(SioPort, DigitalPadPollThroughRegisters) {
  Rig r;
  r.sio.attach_pad(0, std::make_unique<DigitalPad>());
  r.sio.set_buttons(0, pad_button::kUp | pad_button::kCircle);  // bits 4 and 13: ~2010h = DFEFh
  r.sio.io_write(kCtrl, kCtrlSlot1, 2);
  const u8 cmd[5] = {0x01, 0x42, 0x00, 0x00, 0x00};
  const u8 expected[5] = {0xFF, 0x41, 0x5A, 0xEF, 0xDF};
  for (int i = 0; i < 5; ++i) {
    bool acked = false;
    EXPECT_EQ(r.send(cmd[i], acked), expected[i]) << i;
    EXPECT_EQ(acked, i < 4) << i;  // no IRQ7 after the last byte
  }
}

TEST(SioPort, EmptySlotReadsFFWithoutAck) {
  Rig r;
  r.sio.attach_pad(0, std::make_unique<DigitalPad>());
  r.sio.io_write(kCtrl, kCtrlSlot2, 2);
  bool acked = true;
  EXPECT_EQ(r.send(0x01, acked), 0xFF);
  EXPECT_FALSE(acked);
}

TEST(SioPort, AddressByteChoosesPadOrCard) {
  Rig r;
  r.sio.attach_pad(1, std::make_unique<DigitalPad>());
  r.sio.attach_memory_card(1, std::make_unique<MemoryCard>());
  r.sio.io_write(kCtrl, kCtrlSlot2, 2);
  bool acked = false;
  EXPECT_EQ(r.send(0x81, acked), 0xFF);
  EXPECT_TRUE(acked);
  EXPECT_EQ(r.send(0x53, acked), 0x08);  // card FLAG
  r.sio.io_write(kCtrl, 0x0000, 2);      // /JOY2 high ends the card command
  r.sio.io_write(kCtrl, kCtrlSlot2, 2);
  r.send(0x01, acked);
  EXPECT_EQ(r.send(0x42, acked), 0x41);  // pad ID
}

TEST(SioPort, CardAckComesLater) {
  Rig r;
  r.sio.attach_memory_card(0, std::make_unique<MemoryCard>());
  r.sio.io_write(kCtrl, kCtrlSlot1, 2);
  r.sio.io_write(kData, 0x81, 1);
  r.run_for(kByte + MemoryCard::kAckDelay - 1);
  EXPECT_EQ(r.irq.stat(), 0u);
  r.run_for(1);
  EXPECT_EQ(r.irq.stat(), kIStatPad);
}

TEST(SioPort, DeselectRestartsPadCommand) {
  Rig r;
  r.sio.attach_pad(0, std::make_unique<DigitalPad>());
  r.sio.io_write(kCtrl, kCtrlSlot1, 2);
  bool acked = false;
  r.send(0x01, acked);
  r.send(0x42, acked);
  r.sio.io_write(kCtrl, 0x0000, 2);
  r.sio.io_write(kCtrl, kCtrlSlot1, 2);
  EXPECT_EQ(r.send(0x01, acked), 0xFF);
  EXPECT_EQ(r.send(0x42, acked), 0x41);
  EXPECT_EQ(r.send(0x00, acked), 0x5A);
}

TEST(SioPort, TransferWaitsForTxEnable) {
  Rig r;
  r.sio.io_write(kCtrl, 0x1002, 2);  // selected, TXEN off
  r.sio.io_write(kData, 0x01, 1);
  EXPECT_EQ(r.stat() & (kStatTxReady1 | kStatTxReady2), 0u);
  r.run_for(2 * kByte);
  EXPECT_EQ(r.stat() & kStatRxNotEmpty, 0u);
  r.sio.io_write(kCtrl, kCtrlSlot1, 2);
  EXPECT_TRUE(r.stat() & kStatTxReady1);
  r.run_for(kByte);
  EXPECT_TRUE(r.stat() & kStatRxNotEmpty);
}

TEST(SioPort, RxFifoPreviewAndPop) {
  Rig r;
  r.sio.attach_pad(0, std::make_unique<DigitalPad>());
  r.sio.io_write(kCtrl, kCtrlSlot1, 2);
  // Three bytes back to back (the second waits in the TX register), nothing read in between.
  r.sio.io_write(kData, 0x01, 1);
  r.sio.io_write(kData, 0x42, 1);
  EXPECT_EQ(r.stat() & kStatTxReady1, 0u);
  r.run_for(2 * kByte);
  r.sio.io_write(kData, 0x00, 1);
  r.run_for(kByte);
  EXPECT_EQ(r.sio.io_read(kData, 4) & 0x00FFFFFF, 0x5A41FFu);  // oldest in bits 0-7
  EXPECT_EQ(r.sio.io_read(kData, 1), 0x41u);
  EXPECT_EQ(r.sio.io_read(kData, 1), 0x5Au);
  EXPECT_EQ(r.stat() & kStatRxNotEmpty, 0u);
}

TEST(SioPort, RxInterruptAfterNBytes) {
  Rig r;
  r.sio.io_write(kCtrl, 0x0803 | (1 << 8), 2);  // RX IRQ when 2 bytes are in the FIFO
  r.sio.io_write(kData, 0x00, 1);
  r.run_for(kByte);
  EXPECT_EQ(r.irq.stat(), 0u);
  r.sio.io_write(kData, 0x00, 1);
  r.run_for(kByte);
  EXPECT_EQ(r.irq.stat(), kIStatPad);
}

TEST(SioPort, ResetClearsFifoAndTransfer) {
  Rig r;
  r.sio.io_write(kCtrl, kCtrlSlot1, 2);
  r.sio.io_write(kData, 0x01, 1);
  r.run_for(kByte);
  r.sio.io_write(kData, 0x01, 1);
  r.sio.io_write(kCtrl, 0x40, 2);
  EXPECT_EQ(r.stat(), kStatTxReady1 | kStatTxReady2);
  EXPECT_EQ(r.sio.io_read(kCtrl, 2), 0u);
  r.run_for(4 * kByte);
  EXPECT_EQ(r.stat(), kStatTxReady1 | kStatTxReady2);
}

TEST(SioPort, BaudTimerCountsDownFromHalfReload) {
  Rig r;
  r.sio.io_write(kBaud, 0x0088, 2);
  EXPECT_EQ(r.sio.io_read(kStat, 4) >> 11, 0x44u);  // 88h * 1 / 2
  r.run_for(10);
  EXPECT_EQ(r.sio.io_read(kStat, 4) >> 11, 0x44u - 10);
  r.run_for(0x44 - 10);
  EXPECT_EQ(r.sio.io_read(kStat, 4) >> 11, 0x44u);  // reloaded
}

TEST(SioPort, HostApiReachesPads) {
  Rig r;
  r.sio.attach_pad(1, std::make_unique<DualShock>());
  r.sio.set_buttons(1, pad_button::kSquare);
  EXPECT_EQ(r.sio.pad(1)->buttons(), pad_button::kSquare);
  r.sio.set_axes(1, {1, 2, 3, 4});
  EXPECT_EQ(static_cast<DualShock*>(r.sio.pad(1))->axes().left_y, 4);
  EXPECT_EQ(r.sio.rumble(0).large, 0);  // empty port
  r.sio.set_buttons(0, pad_button::kSquare);  // empty port: ignored
}

TEST(SioPort, SaveStateMidTransferGivesSameFuture) {
  auto setup = [](Rig& r) {
    r.sio.attach_pad(0, std::make_unique<DualShock>());
    r.sio.attach_memory_card(1, std::make_unique<MemoryCard>());
    r.sio.set_buttons(0, pad_button::kL1);
  };
  Rig a;
  setup(a);
  a.sio.io_write(kCtrl, kCtrlSlot1, 2);
  bool acked = false;
  a.send(0x01, acked);
  a.sio.io_write(kData, 0x42, 1);
  a.run_for(100);  // mid-byte
  StateIO w;
  a.sched.do_state(w);
  a.irq.do_state(w);
  a.sio.do_state(w);

  Rig b;
  setup(b);
  b.sio.set_buttons(0, 0);  // host input is part of the state
  StateIO rd(w.buffer().data(), w.buffer().size());
  b.sched.do_state(rd);
  b.irq.do_state(rd);
  b.sio.do_state(rd);
  EXPECT_TRUE(rd.at_end());
  for (Rig* r : {&a, &b}) r->run_for(kByte);
  EXPECT_EQ(b.sio.io_read(kData, 1), a.sio.io_read(kData, 1));
  for (u8 byte : {0x00, 0x00, 0x00}) {
    bool x = false, y = false;
    EXPECT_EQ(b.send(byte, y), a.send(byte, x));
    EXPECT_EQ(x, y);
  }
  EXPECT_EQ(b.sched.now(), a.sched.now());
}

TEST(SioPort, SaveStateRefusesDifferentDevices) {
  Rig a;
  a.sio.attach_pad(0, std::make_unique<DualShock>());
  StateIO w;
  a.sio.do_state(w);
  Rig b;
  b.sio.attach_pad(0, std::make_unique<DigitalPad>());
  StateIO rd(w.buffer().data(), w.buffer().size());
  try {
    b.sio.do_state(rd);
    FAIL() << "no error";
  } catch (const StateError& e) {
    EXPECT_NE(std::string(e.what()).find("DualShock in port 1"), std::string::npos) << e.what();
  }
}

TEST(SioPort, ConsoleMapsSio0WithDigitalPadInPort1) {
  Console c;
  ASSERT_NE(c.sio0().pad(0), nullptr);
  EXPECT_EQ(c.sio0().pad(0)->kind(), Pad::Kind::Digital);
  EXPECT_EQ(c.sio0().pad(1), nullptr);
  u32 v = 0;
  ASSERT_TRUE(c.bus().write16(0xBF80104E, 0x0088));
  ASSERT_TRUE(c.bus().read16(0xBF80104E, v));
  EXPECT_EQ(v, 0x0088u);
  ASSERT_TRUE(c.bus().read32(0xBF801044, v));
  EXPECT_EQ(v & 0x7FF, kStatTxReady1 | kStatTxReady2);
}

}  // namespace
}  // namespace psx
