// SIO0: the controller and memory card serial port (psx-spx "Controller and Memory Card I/O
// Ports", 1F801040h-1F80104Fh): JOY_DATA, JOY_STAT, JOY_MODE, JOY_CTRL, JOY_BAUD, the baud-rate
// timed byte transfers, the /ACK pulses and IRQ7. Two slots, each with an optional controller and
// an optional memory card; /JOYn selects both, the first byte (01h or 81h) picks which answers.
// Also the host input API: buttons and sticks in, rumble motor drive out.
#pragma once
#include <array>
#include <memory>

#include "core/io_device.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "core/sio/baud_timer.h"
#include "core/sio/memory_card.h"
#include "core/sio/pad.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

class Sio0 final : public IoDevice {
 public:
  static constexpr u32 kBase = 0x1F801040;
  static constexpr u32 kSize = 16;
  static constexpr int kPorts = 2;  // index 0 = controller/memory card slot 1, 1 = slot 2
  // /ACK stays low for about 100 cycles (psx-spx "/IRQ7 (/ACK)").
  static constexpr Cycles kAckPulse = 100;

  Sio0(Scheduler& sched, InterruptController& irq);

  u32 io_read(u32 offset, u32 width) override;
  void io_write(u32 offset, u32 value, u32 width) override;

  // Plugging devices is configuration (nullptr unplugs). A save state records which kinds are
  // plugged in and refuses to load into a console wired differently.
  void attach_pad(int port, std::unique_ptr<Pad> pad);
  void attach_memory_card(int port, std::unique_ptr<MemoryCard> card);
  Pad* pad(int port) { return slots_.at(port).pad.get(); }
  MemoryCard* memory_card(int port) { return slots_.at(port).card.get(); }

  // Host input API, called between emulation steps. `pressed` uses the pad_button bits
  // (1 = pressed). Calls for an empty port do nothing; rumble of an empty port is zero.
  void set_buttons(int port, u16 pressed);
  void set_axes(int port, const AnalogAxes& axes);
  Rumble rumble(int port) const;

  void do_state(StateIO& s);

 private:
  // JOY_CTRL bits.
  static constexpr u16 kCtrlTxEnable = 1u << 0;
  static constexpr u16 kCtrlSelect = 1u << 1;  // /JOYn low
  static constexpr u16 kCtrlRxEnable = 1u << 2;
  static constexpr u16 kCtrlAcknowledge = 1u << 4;
  static constexpr u16 kCtrlReset = 1u << 6;
  static constexpr u16 kCtrlTxIrq = 1u << 10;
  static constexpr u16 kCtrlRxIrq = 1u << 11;
  static constexpr u16 kCtrlAckIrq = 1u << 12;
  static constexpr u16 kCtrlPort = 1u << 13;
  static constexpr u16 kCtrlStored = 0x3F2F;  // bits 4, 6, 7, 14, 15 are never read back
  static constexpr u16 kModeStored = 0x013F;

  // Which device on the selected slot answers the bytes of the current selection.
  enum class Target : u8 { None, Pad, MemoryCard, Nobody };

  struct Slot {
    std::unique_ptr<Pad> pad;
    std::unique_ptr<MemoryCard> card;
  };

  u32 read_stat() const;
  u8 pop_rx();
  void write_ctrl(u16 value);
  void write_tx(u8 value);
  void reset();
  void try_start_transfer();
  void on_transfer_done();
  void on_ack_event();
  SioDevice::Reply exchange(u8 command, Cycles& ack_delay);
  void end_selection();
  void raise_irq();
  Cycles byte_cycles() const { return 16 * sio_baud_half_period(baud_, mode_); }

  Scheduler& sched_;
  InterruptController& irq_;
  Scheduler::Handle transfer_event_;
  Scheduler::Handle ack_event_;
  std::array<Slot, kPorts> slots_;

  // Registers.
  u16 mode_ = 0;
  u16 ctrl_ = 0;
  u16 baud_ = 0;
  BaudTimer baud_timer_;  // reloaded when JOY_BAUD is written

  // TX: one byte waiting in the TX register, one in the shift register.
  u8 tx_buffer_ = 0;
  bool tx_buffer_full_ = false;
  bool tx_latched_enable_ = false;  // TXEN as it was when JOY_TX_DATA was written
  u8 tx_shift_ = 0;
  bool transferring_ = false;

  // RX FIFO (8 entries).
  std::array<u8, 8> rx_fifo_{};
  u8 rx_head_ = 0;
  u8 rx_count_ = 0;

  bool ack_low_ = false;      // JOY_STAT.7: /ACK input is low
  bool ack_pending_ = false;  // ack_event_ is booked for the falling edge (else the rising edge)
  bool irq_flag_ = false;     // JOY_STAT.9

  Target target_ = Target::None;
  u8 selected_port_ = 0;  // slot whose /JOYn is low while ctrl_ has kCtrlSelect
};

}  // namespace psx
