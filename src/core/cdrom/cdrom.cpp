// CD-ROM controller host interface: banked registers, FIFOs, interrupt flag/enable, DMA, state.
#include "core/cdrom/cdrom.h"

#include <algorithm>

namespace psx {

Cdrom::Cdrom(Scheduler& sched, InterruptController& irq) : sched_(sched), irq_(irq) {
  ev_command_ = sched_.add_event("cdrom.command", [this](Cycles late) { command_event(late); });
  ev_second_ = sched_.add_event("cdrom.second", [this](Cycles late) { second_event(late); });
  ev_drive_ = sched_.add_event("cdrom.drive", [this](Cycles late) { drive_event(late); });
  ev_deliver_ = sched_.add_event("cdrom.deliver", [this](Cycles late) { deliver_queued(late); });
}

void Cdrom::insert_disc(std::unique_ptr<disc::Disc> d) {
  disc_ = std::move(d);
  stop_drive();
  motor_on_ = disc_ != nullptr && !lid_open_;
  position_ = setloc_ = disc::kLeadInSectors;
}

void Cdrom::set_lid_open(bool open) {
  lid_open_ = open;
  if (open) {
    // Opening the lid stops the motor and sets the shell-open bit until a Getstat after closing.
    shell_open_latch_ = true;
    stop_drive();
    motor_on_ = false;
  } else {
    motor_on_ = disc_ != nullptr;
  }
}

void Cdrom::log(const std::string& what) {
  if (on_log) on_log("cdrom: " + what);
}

Cdrom::Response Cdrom::make(u8 irq, std::initializer_list<u8> bytes) const {
  Response r;
  r.irq = irq;
  for (u8 b : bytes) r.bytes[r.size++] = b;
  return r;
}

u8 Cdrom::status_register() const {
  u8 v = index_;
  if (xa_active_) v |= 0x04;                              // ADPBUSY
  if (param_count_ == 0) v |= 0x08;                       // PRMEMPT
  if (param_count_ < 16) v |= 0x10;                       // PRMWRDY
  if (response_pos_ < response_.size) v |= 0x20;          // RSLRRDY
  if (data_pos_ < data_size_) v |= 0x40;                  // DRQSTS
  if (busy_) v |= 0x80;                                   // BUSYSTS
  return v;
}

u8 Cdrom::read_data_byte() {
  // Reading an empty data FIFO returns the last byte again (psx-spx); zero before any data.
  if (data_pos_ >= data_size_) return data_size_ ? data_[data_size_ - 1] : 0;
  return data_[data_pos_++];
}

u32 Cdrom::io_read(u32 offset, u32 width) {
  switch (offset & 3) {
    case 0:
      return status_register();
    case 1: {
      // The response FIFO: bytes past the response read as zero.
      u8 v = response_pos_ < response_.size ? response_.bytes[response_pos_] : 0;
      if (response_pos_ < response_.size) ++response_pos_;
      return v;
    }
    case 2: {
      u32 v = 0;
      for (u32 i = 0; i < width; ++i) v |= static_cast<u32>(read_data_byte()) << (8 * i);
      return v;
    }
    default:
      // Index 0/2: interrupt enable; 1/3: interrupt flag. Unused upper bits read as 1.
      return (index_ & 1) ? (0xE0 | int_flag_) : (0xE0 | int_enable_);
  }
}

void Cdrom::io_write(u32 offset, u32 value, u32 width) {
  const u8 v = static_cast<u8>(value);
  switch ((offset & 3) << 2 | index_) {
    case 0x0: case 0x1: case 0x2: case 0x3:
      index_ = v & 3;
      break;
    case 0x4:  // command
      if (busy_) log("command " + std::to_string(v) + " written while busy; the previous one is dropped");
      command_ = v;
      busy_ = true;
      sched_.schedule(ev_command_, first_response_time(v));
      break;
    case 0x5: case 0x6:  // sound map data out / coding info: the sound map feature is unused
      break;
    case 0x7: volume_pending_[2] = v; break;  // right CD -> right SPU
    case 0x8:
      if (param_count_ < 16) params_[param_count_++] = v;
      break;
    case 0x9:
      int_enable_ = v & 0x1F;
      break;
    case 0xA: volume_pending_[0] = v; break;  // left CD -> left SPU
    case 0xB: volume_pending_[3] = v; break;  // right CD -> left SPU
    case 0xC: write_request(v); break;
    case 0xD: write_ack(v); break;
    case 0xE: volume_pending_[1] = v; break;  // left CD -> right SPU
    case 0xF:
      adpcm_muted_ = v & 0x01;
      if (v & 0x20) volume_ = volume_pending_;
      break;
  }
}

// Request register: BFRD (bit 7) moves the buffered sector into the data FIFO; clearing it
// empties the FIFO.
Cycles Cdrom::first_response_time(u8 command) {
  // Init and ReadTOC initialise the drive before answering; the other commands answer at
  // GetStat's pace, sooner while the motor is off (psx-spx "CDROM - Response Timings"; that
  // time has no hardware spread recorded, so it stays fixed).
  if (command != 0x0A && command != 0x1E && !motor_on_) return kFirstResponseStopped;
  ack_random_ ^= ack_random_ << 13;
  ack_random_ ^= ack_random_ >> 17;
  ack_random_ ^= ack_random_ << 5;
  if (command == 0x0A || command == 0x1E) return kAckInitMin + ack_random_ % kAckInitSpan;
  return kAckMin + ack_random_ % kAckSpan;
}

void Cdrom::write_request(u8 v) {
  if (!(v & 0x80)) {
    data_size_ = data_pos_ = 0;
    return;
  }
  if (data_pos_ < data_size_ || !sector_ready_) return;
  std::copy(sector_.begin(), sector_.begin() + sector_size_, data_.begin());
  data_size_ = sector_size_;
  data_pos_ = 0;
  sector_ready_ = false;
}

void Cdrom::write_ack(u8 v) {
  int_flag_ &= ~(v & 0x1F);
  if (v & 0x40) param_count_ = 0;  // CLRPRM
  // The next response waits until the current interrupt has been acknowledged.
  if ((int_flag_ & 7) == 0 && has_queued_ && !sched_.pending(ev_deliver_)) sched_.schedule(ev_deliver_, kAckToNextIrq);
}

void Cdrom::deliver(const Response& r) {
  if ((int_flag_ & 7) != 0 || sched_.pending(ev_deliver_)) {
    // A data sector may replace an older undelivered one; a command response is never dropped.
    if (has_queued_ && queued_.irq != 1 && r.irq == 1) return;
    queued_ = r;
    has_queued_ = true;
    return;
  }
  response_ = r;
  response_pos_ = 0;
  int_flag_ = (int_flag_ & ~7) | r.irq;
  if (int_flag_ & int_enable_ & 0x1F) irq_.raise(Irq::Cdrom);
}

void Cdrom::deliver_queued(Cycles) {
  if (!has_queued_) return;
  has_queued_ = false;
  deliver(queued_);
}

void Cdrom::dma_write(const u32*, u32 count) {
  log("DMA write of " + std::to_string(count) + " words to the CD-ROM (channel 3 only reads); ignored");
}

void Cdrom::dma_read(u32* words, u32 count) {
  for (u32 i = 0; i < count; ++i) {
    u32 w = 0;
    for (int b = 0; b < 4; ++b) w |= static_cast<u32>(read_data_byte()) << (8 * b);
    words[i] = w;
  }
}

void Cdrom::do_state(StateIO& s) {
  const u32 version = s.section("CDRM", 2, 1);
  s.pod(index_);
  s.pod(params_);
  s.pod(param_count_);
  s.pod(response_);
  s.pod(response_pos_);
  s.pod(int_enable_);
  s.pod(int_flag_);
  s.boolean(busy_);
  s.pod(command_);
  s.pod(queued_);
  s.boolean(has_queued_);
  s.pod(second_);
  s.pod(sector_);
  s.pod(sector_size_);
  s.boolean(sector_ready_);
  s.pod(data_);
  s.pod(data_size_);
  s.pod(data_pos_);
  s.pod(drive_);
  s.pod(after_seek_);
  s.boolean(motor_on_);
  s.boolean(lid_open_);
  s.boolean(shell_open_latch_);
  s.pod(mode_);
  s.pod(position_);
  s.pod(setloc_);
  s.pod(seek_target_);
  s.boolean(setloc_pending_);
  s.pod(filter_file_);
  s.pod(filter_channel_);
  s.boolean(muted_);
  s.pod(scan_);
  s.pod(last_header_);
  s.boolean(xa_active_);
  s.pod(volume_pending_);
  s.pod(volume_);
  s.boolean(adpcm_muted_);
  xa_.do_state(s);
  audio_.do_state(s);
  s.pod_since(version, 2, ack_random_, kAckSeed);  // version 2: acknowledge times vary
  if (s.loading() && ack_random_ == 0) s.fail("CD-ROM acknowledge generator state is zero");
  if (s.loading() && (param_count_ > 16 || response_.size > 16 || queued_.size > 16 || sector_size_ > sector_.size() ||
                      data_size_ > data_.size() || data_pos_ > data_size_ || static_cast<u8>(drive_) > 3 ||
                      static_cast<u8>(after_seek_) > 3 || static_cast<u8>(second_) > 7))
    s.fail("CD-ROM state out of range");
  s.end_section("CDRM");
}

}  // namespace psx
