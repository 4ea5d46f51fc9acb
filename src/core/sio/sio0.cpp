// SIO0 registers, byte transfer timing, /ACK and IRQ7, slot selection and device routing.
#include "core/sio/sio0.h"

#include <algorithm>
#include <string>

namespace psx {

namespace {
constexpr u8 kAddressPad = 0x01;
constexpr u8 kAddressMemoryCard = 0x81;

u32 width_mask(u32 width) { return width >= 4 ? 0xFFFFFFFFu : (1u << (8 * width)) - 1; }

const char* kind_name(u8 kind) {
  switch (kind) {
    case 0: return "no controller";
    case static_cast<u8>(Pad::Kind::Digital): return "a digital pad";
    case static_cast<u8>(Pad::Kind::DualShock): return "a DualShock";
    default: return "an unknown controller";
  }
}
}  // namespace

Sio0::Sio0(Scheduler& sched, InterruptController& irq)
    : sched_(sched),
      irq_(irq),
      transfer_event_(sched.add_event("sio0.transfer", [this](Cycles) { on_transfer_done(); })),
      ack_event_(sched.add_event("sio0.ack", [this](Cycles) { on_ack_event(); })) {}

void Sio0::attach_pad(int port, std::unique_ptr<Pad> pad) {
  slots_.at(port).pad = std::move(pad);
  if (target_ != Target::None && port == selected_port_) target_ = Target::Nobody;
}

void Sio0::attach_memory_card(int port, std::unique_ptr<MemoryCard> card) {
  slots_.at(port).card = std::move(card);
  if (target_ != Target::None && port == selected_port_) target_ = Target::Nobody;
}

void Sio0::set_buttons(int port, u16 pressed) {
  if (Pad* p = pad(port)) p->set_buttons(pressed);
}

void Sio0::set_axes(int port, const AnalogAxes& axes) {
  if (Pad* p = pad(port)) p->set_axes(axes);
}

Rumble Sio0::rumble(int port) const {
  const Pad* p = slots_.at(port).pad.get();
  return p ? p->rumble() : Rumble{};
}

// Registers as 32-bit words: 0 JOY_DATA, 4 JOY_STAT, 8 JOY_MODE|JOY_CTRL<<16, C JOY_BAUD<<16.
// Narrow reads take their lanes from the word; any read of JOY_DATA pops one FIFO byte.
u32 Sio0::io_read(u32 offset, u32 width) {
  u32 word = 0;
  switch (offset & ~3u) {
    case 0x0:
      // Oldest RX byte, then up to three more FIFO entries as a preview (psx-spx JOY_RX_DATA).
      for (u32 i = 0; i < 4; ++i) word |= u32{rx_fifo_[(rx_head_ + i) & 7]} << (8 * i);
      pop_rx();
      break;
    case 0x4: word = read_stat(); break;
    case 0x8: word = mode_ | u32{ctrl_} << 16; break;
    case 0xC: word = u32{baud_} << 16; break;
    default: break;
  }
  return (word >> (8 * (offset & 3))) & width_mask(width);
}

void Sio0::io_write(u32 offset, u32 value, u32 width) {
  switch (offset) {
    case 0x0: write_tx(static_cast<u8>(value)); break;
    case 0x8:
      mode_ = static_cast<u16>(value & kModeStored);
      if (width == 4) write_ctrl(static_cast<u16>(value >> 16));
      break;
    case 0xA: write_ctrl(static_cast<u16>(value)); break;
    case 0xC:
      if (width == 4) {
        baud_ = static_cast<u16>(value >> 16);
        baud_timer_.reload(sched_.now());
      }
      break;
    case 0xE:
      baud_ = static_cast<u16>(value);
      baud_timer_.reload(sched_.now());
      break;
    default: break;  // JOY_STAT is read-only
  }
}

u32 Sio0::read_stat() const {
  u32 v = 0;
  if (!tx_buffer_full_) v |= 1u << 0;                  // TX ready 1: TX register free
  if (rx_count_ != 0) v |= 1u << 1;                    // RX FIFO not empty
  if (!tx_buffer_full_ && !transferring_) v |= 1u << 2;  // TX ready 2: all sent
  if (ack_low_) v |= 1u << 7;
  if (irq_flag_) v |= 1u << 9;
  return v | baud_timer_.stat_bits(baud_, mode_, sched_.now());
}

u8 Sio0::pop_rx() {
  const u8 b = rx_fifo_[rx_head_];
  if (rx_count_ == 0) return b;  // empty: the FIFO read pointer stays put
  rx_head_ = (rx_head_ + 1) & 7;
  --rx_count_;
  return b;
}

void Sio0::write_ctrl(u16 value) {
  if (value & kCtrlReset) {
    reset();
    return;
  }
  const bool was_selected = ctrl_ & kCtrlSelect;
  ctrl_ = value & kCtrlStored;
  // Acknowledge clears JOY_STAT.9 (and the parity flag, never set here). psx-spx notes that real
  // hardware cannot clear it while /ACK is still low; the emulated CPU and /ACK timings are not
  // exact enough to reproduce that ~100-cycle window without hanging programs that acknowledge
  // early, so the flag always clears.
  if (value & kCtrlAcknowledge) irq_flag_ = false;
  const bool selected = ctrl_ & kCtrlSelect;
  const u8 port = (ctrl_ & kCtrlPort) ? 1 : 0;
  // /JOYn going high (or the select moving to the other slot) ends the devices' commands.
  if (was_selected && (!selected || port != selected_port_)) end_selection();
  if (selected) selected_port_ = port;
  try_start_transfer();
}

// JOY_CTRL.6: most JOY registers back to zero; the transfer in flight is dropped.
void Sio0::reset() {
  end_selection();
  sched_.cancel(transfer_event_);
  sched_.cancel(ack_event_);
  mode_ = 0;
  ctrl_ = 0;
  tx_buffer_full_ = false;
  tx_latched_enable_ = false;
  transferring_ = false;
  rx_head_ = 0;
  rx_count_ = 0;
  ack_low_ = false;
  ack_pending_ = false;
  irq_flag_ = false;
}

void Sio0::write_tx(u8 value) {
  tx_buffer_ = value;
  tx_buffer_full_ = true;
  tx_latched_enable_ = ctrl_ & kCtrlTxEnable;
  try_start_transfer();
}

// A byte moves from the TX register to the shift register once TXEN (now, or latched when the
// byte was written) allows it and the previous byte has been shifted out.
void Sio0::try_start_transfer() {
  if (transferring_ || !tx_buffer_full_) return;
  if (!(ctrl_ & kCtrlTxEnable) && !tx_latched_enable_) return;
  tx_shift_ = tx_buffer_;
  tx_buffer_full_ = false;
  transferring_ = true;
  sched_.schedule(transfer_event_, byte_cycles());
  if (ctrl_ & kCtrlTxIrq) raise_irq();  // TX ready 1
}

void Sio0::on_transfer_done() {
  transferring_ = false;
  Cycles ack_delay = 0;
  const SioDevice::Reply reply = exchange(tx_shift_, ack_delay);
  // Received bytes are kept while /JOYn is low, or once after RXEN forced it (RXEN auto-clears).
  if ((ctrl_ & kCtrlSelect) || (ctrl_ & kCtrlRxEnable)) {
    if (rx_count_ < rx_fifo_.size()) ++rx_count_;  // full: the newest entry is overwritten
    rx_fifo_[(rx_head_ + rx_count_ - 1) & 7] = reply.data;
  }
  ctrl_ &= static_cast<u16>(~kCtrlRxEnable);
  if (reply.ack) {
    ack_pending_ = true;
    sched_.schedule(ack_event_, ack_delay);
  }
  if ((ctrl_ & kCtrlRxIrq) && rx_count_ >= (1u << ((ctrl_ >> 8) & 3))) raise_irq();
  if (ctrl_ & kCtrlTxIrq) raise_irq();  // TX ready 2
  try_start_transfer();
}

// /ACK falls after the device's delay (IRQ7 if enabled) and rises kAckPulse cycles later.
void Sio0::on_ack_event() {
  if (!ack_pending_) {
    ack_low_ = false;
    return;
  }
  ack_pending_ = false;
  ack_low_ = true;
  if (ctrl_ & kCtrlAckIrq) raise_irq();
  sched_.schedule(ack_event_, kAckPulse);
}

// The first byte after /JOYn falls addresses the controller (01h) or the memory card (81h) of the
// selected slot; without such a device nothing drives the data line and it reads FFh.
SioDevice::Reply Sio0::exchange(u8 command, Cycles& ack_delay) {
  if (!(ctrl_ & kCtrlSelect)) return {};
  Slot& slot = slots_[selected_port_];
  if (target_ == Target::None) {
    if (command == kAddressPad && slot.pad)
      target_ = Target::Pad;
    else if (command == kAddressMemoryCard && slot.card)
      target_ = Target::MemoryCard;
    else
      target_ = Target::Nobody;
  }
  SioDevice* dev = nullptr;
  if (target_ == Target::Pad) dev = slot.pad.get();
  if (target_ == Target::MemoryCard) dev = slot.card.get();
  if (!dev) return {};
  const SioDevice::Reply reply = dev->transfer(command);
  ack_delay = dev->ack_delay();
  return reply;
}

void Sio0::end_selection() {
  Slot& slot = slots_[selected_port_];
  if (slot.pad) slot.pad->deselect();
  if (slot.card) slot.card->deselect();
  target_ = Target::None;
  // A deselected device no longer pulls /ACK; a pulse already under way finishes.
  if (ack_pending_) {
    ack_pending_ = false;
    sched_.cancel(ack_event_);
  }
}

void Sio0::raise_irq() {
  if (irq_flag_) return;  // I_STAT.7 sees only the rising edge of JOY_STAT.9
  irq_flag_ = true;
  irq_.raise(Irq::PadMemcard);
}

void Sio0::do_state(StateIO& s) {
  s.section("SIO0", 1);
  s.pod(mode_);
  s.pod(ctrl_);
  s.pod(baud_);
  baud_timer_.do_state(s);
  s.pod(tx_buffer_);
  s.boolean(tx_buffer_full_);
  s.boolean(tx_latched_enable_);
  s.pod(tx_shift_);
  s.boolean(transferring_);
  s.pod(rx_fifo_);
  s.pod(rx_head_);
  s.pod(rx_count_);
  s.boolean(ack_low_);
  s.boolean(ack_pending_);
  s.boolean(irq_flag_);
  s.pod(target_);
  s.pod(selected_port_);
  if (s.loading() && (rx_head_ > 7 || rx_count_ > 8 || selected_port_ >= kPorts ||
                      static_cast<u8>(target_) > static_cast<u8>(Target::Nobody)))
    s.fail("SIO0 state out of range");
  for (int port = 0; port < kPorts; ++port) {
    Slot& slot = slots_[port];
    u8 pad_kind = slot.pad ? static_cast<u8>(slot.pad->kind()) : 0;
    u8 has_card = slot.card ? 1 : 0;
    const u8 here_kind = pad_kind, here_card = has_card;
    s.pod(pad_kind);
    s.pod(has_card);
    const std::string where = " in port " + std::to_string(port + 1);
    if (s.loading() && pad_kind != here_kind)
      s.fail(std::string("save state has ") + kind_name(pad_kind) + where + ", this console has " +
             kind_name(here_kind));
    if (s.loading() && has_card != here_card)
      s.fail(std::string("save state has ") + (has_card ? "a" : "no") + " memory card" + where +
             ", this console has " + (here_card ? "one" : "none"));
    if (slot.pad) slot.pad->do_state(s);
    if (slot.card) slot.card->do_state(s);
  }
  s.end_section("SIO0");
}

}  // namespace psx
