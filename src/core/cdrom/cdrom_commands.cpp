// CD-ROM controller commands (psx-spx "CDROM Controller Command Summary"): parameter checks,
// first responses (INT3 acknowledge or INT5 error) and the second responses (INT2 complete,
// INT5 error) that arrive later on the scheduler.
#include "core/cdrom/cdrom.h"

namespace psx {
namespace {

// Parameter counts: minimum and maximum per command (Play takes an optional track).
struct ParamRange {
  u8 min, max;
};
ParamRange param_range(u8 cmd) {
  switch (cmd) {
    case 0x02: return {3, 3};  // Setloc
    case 0x03: return {0, 1};  // Play
    case 0x0D: return {2, 2};  // Setfilter
    case 0x0E: return {1, 1};  // Setmode
    case 0x12: return {1, 1};  // SetSession
    case 0x14: return {1, 1};  // GetTD
    case 0x19: return {1, 16};  // Test
    default: return {0, 0};
  }
}

bool needs_disc(u8 cmd) {
  switch (cmd) {
    case 0x03: case 0x04: case 0x05: case 0x06: case 0x07: case 0x11: case 0x12: case 0x15: case 0x16:
    case 0x1B: case 0x1E:
      return true;
    default:
      return false;
  }
}

}  // namespace

void Cdrom::error(u8 code) { deliver(make(5, {static_cast<u8>(stat() | kStatError), code})); }

bool Cdrom::check_params(u8 cmd) {
  ParamRange r = param_range(cmd);
  if (param_count_ < r.min || param_count_ > r.max) {
    error(kErrParameterCount);
    return false;
  }
  return true;
}

void Cdrom::command_event(Cycles) {
  busy_ = false;
  u8 cmd = command_;
  execute(cmd);
  param_count_ = 0;
}

void Cdrom::schedule_second(Second kind, Cycles delay) {
  second_ = kind;
  sched_.schedule(ev_second_, delay);
}

void Cdrom::execute(u8 cmd) {
  const bool known = (cmd >= 0x01 && cmd <= 0x16) || cmd == 0x19 || cmd == 0x1A || cmd == 0x1B || cmd == 0x1E;
  if (!known) {
    log("unknown command " + std::to_string(cmd));
    error(kErrInvalidCommand);
    return;
  }
  if (!check_params(cmd)) return;
  if (lid_open_ && cmd != 0x01 && cmd != 0x19) {
    deliver(make(5, {static_cast<u8>(stat() | kStatError), kErrNotReady}));
    return;
  }
  if (!disc_ && needs_disc(cmd)) {
    error(kErrNotReady);
    return;
  }
  const u8 p0 = params_[0];
  switch (cmd) {
    case 0x01:  // Getstat: also clears the shell-open bit once the lid is closed again
      deliver(make(3, {stat()}));
      if (!lid_open_) shell_open_latch_ = false;
      break;
    case 0x02: cmd_setloc(); break;
    case 0x03: cmd_play(); break;
    case 0x04: case 0x05:  // Forward / Backward: fast scan while playing
      if (drive_ != Drive::Playing) {
        error(kErrNotReady);
        break;
      }
      scan_ = cmd == 0x04 ? 1 : -1;
      deliver(make(3, {stat()}));
      break;
    case 0x06: case 0x1B: cmd_read(); break;  // ReadN / ReadS
    case 0x07:  // MotorOn: an error when the motor already turns
      if (motor_on_) {
        error(kErrParameterCount);
        break;
      }
      deliver(make(3, {stat()}));
      schedule_second(Second::MotorOn, kMotorSpinUp);
      break;
    case 0x08: {  // Stop
      Cycles t = !motor_on_ ? kStopWhenStopped : (mode_ & kModeDoubleSpeed) ? kStopDouble : kStopSingle;
      stop_drive();
      deliver(make(3, {stat()}));
      schedule_second(Second::Stop, t);
      break;
    }
    case 0x09: {  // Pause: the first response still shows the read/play bits
      Cycles t = drive_ == Drive::Idle ? kPauseWhenPaused : (mode_ & kModeDoubleSpeed) ? kPauseDouble : kPauseSingle;
      deliver(make(3, {stat()}));
      stop_drive();
      schedule_second(Second::Pause, t);
      break;
    }
    case 0x0A:  // Init: mode 0x20, motor on, abort reading
      deliver(make(3, {stat()}));
      stop_drive();
      mode_ = 0x20;
      motor_on_ = disc_ != nullptr;
      schedule_second(Second::Init, kFirstResponse);
      break;
    case 0x0B: muted_ = true, deliver(make(3, {stat()})); break;
    case 0x0C: muted_ = false, deliver(make(3, {stat()})); break;
    case 0x0D:  // Setfilter file, channel (XA-ADPCM sectors to play when filtering)
      if (filter_file_ != p0 || filter_channel_ != params_[1]) xa_.reset();
      filter_file_ = p0, filter_channel_ = params_[1];
      deliver(make(3, {stat()}));
      break;
    case 0x0E: mode_ = p0, deliver(make(3, {stat()})); break;
    case 0x0F: deliver(make(3, {stat(), mode_, 0, filter_file_, filter_channel_})); break;  // Getparam
    case 0x10:  // GetlocL: header and subheader of the last data sector
      if (drive_ == Drive::Playing) {
        error(kErrNotReady);
        break;
      }
      deliver(make(3, {last_header_[0], last_header_[1], last_header_[2], last_header_[3], last_header_[4],
                       last_header_[5], last_header_[6], last_header_[7]}));
      break;
    case 0x11: cmd_getlocp(); break;
    case 0x12:  // SetSession: this drive's discs have one session
      if (p0 == 0) {
        error(kErrInvalidParameter);
        break;
      }
      deliver(make(3, {stat()}));
      schedule_second(p0 == 1 ? Second::SetSession : Second::None, kSetSessionTime);
      break;
    case 0x13: {  // GetTN: first and last track numbers
      const auto& t = disc_->tracks();
      deliver(make(3, {stat(), disc::to_bcd(t.front().number), disc::to_bcd(t.back().number)}));
      break;
    }
    case 0x14: cmd_gettd(); break;
    case 0x15: case 0x16: cmd_seek(); break;  // SeekL / SeekP
    case 0x19: cmd_test(); break;
    case 0x1A:  // GetID
      deliver(make(3, {stat()}));
      schedule_second(Second::GetId, kGetIdSecond);
      break;
    case 0x1E:  // ReadTOC
      deliver(make(3, {stat()}));
      stop_drive();
      schedule_second(Second::ReadToc, kReadTocTime);
      break;
  }
}

void Cdrom::cmd_setloc() {
  for (int i = 0; i < 3; ++i) {
    if (!disc::valid_bcd(params_[i])) {
      error(kErrInvalidParameter);
      return;
    }
  }
  disc::Msf m{static_cast<u8>(disc::from_bcd(params_[0])), static_cast<u8>(disc::from_bcd(params_[1])),
              static_cast<u8>(disc::from_bcd(params_[2]))};
  if (m.second >= 60 || m.sector >= disc::kSectorsPerSecond) {
    error(kErrInvalidParameter);
    return;
  }
  setloc_ = m.to_sectors();
  setloc_pending_ = true;
  deliver(make(3, {stat()}));
}

void Cdrom::cmd_play() {
  u32 target = position_;
  if (param_count_ == 1 && params_[0] != 0) {
    u32 track = disc::from_bcd(params_[0]);
    const disc::Track* found = nullptr;
    for (const disc::Track& t : disc_->tracks())
      if (t.number == track) found = &t;
    // A track past the last one plays from the first (psx-spx: "Play ... track number").
    target = found ? found->index1 : disc_->tracks().front().index1;
  } else if (setloc_pending_) {
    target = setloc_;
  }
  setloc_pending_ = false;
  scan_ = 0;
  deliver(make(3, {stat()}));
  start_seek(target, AfterSeek::Play);
}

void Cdrom::cmd_read() {
  deliver(make(3, {stat()}));
  if (setloc_pending_ || drive_ == Drive::Playing || drive_ == Drive::Idle) {
    u32 target = setloc_pending_ ? setloc_ : position_;
    setloc_pending_ = false;
    start_seek(target, AfterSeek::Read);
  }
}

void Cdrom::cmd_seek() {
  deliver(make(3, {stat()}));
  u32 target = setloc_pending_ ? setloc_ : position_;
  setloc_pending_ = false;
  start_seek(target, AfterSeek::SeekDone);
}

void Cdrom::cmd_gettd() {
  if (!disc::valid_bcd(params_[0])) {
    error(kErrInvalidParameter);
    return;
  }
  u32 track = disc::from_bcd(params_[0]);
  u32 abs = 0;
  if (track == 0) {
    abs = disc_->lead_out();
  } else {
    const disc::Track* found = nullptr;
    for (const disc::Track& t : disc_->tracks())
      if (t.number == track) found = &t;
    if (!found) {
      error(kErrInvalidParameter);
      return;
    }
    abs = found->index1;
  }
  disc::Msf m = disc::Msf::from_sectors(abs);
  deliver(make(3, {stat(), disc::to_bcd(m.minute), disc::to_bcd(m.second)}));
}

// GetlocP: track, index, time within the track (counting down in the pregap), absolute time.
void Cdrom::cmd_getlocp() {
  const disc::Track* t = disc_->track_at(position_);
  u8 track = t ? t->number : 0xAA;  // 0xAA = lead-out
  bool pregap = t && position_ < t->index1;
  u32 rel = !t ? position_ - disc_->lead_out() : pregap ? t->index1 - position_ : position_ - t->index1;
  disc::Msf r = disc::Msf::from_sectors(rel), a = disc::Msf::from_sectors(position_);
  deliver(make(3, {static_cast<u8>(t ? disc::to_bcd(track) : track), static_cast<u8>(pregap ? 0 : 1),
                   disc::to_bcd(r.minute), disc::to_bcd(r.second), disc::to_bcd(r.sector), disc::to_bcd(a.minute),
                   disc::to_bcd(a.second), disc::to_bcd(a.sector)}));
}

void Cdrom::cmd_test() {
  switch (params_[0]) {
    case 0x20:  // controller BIOS date and version (vC0, the common SCPH-1001 controller)
      deliver(make(3, {0x94, 0x09, 0x19, 0xC0}));
      break;
    default:
      log("Test sub-function " + std::to_string(params_[0]) + " not provided by this controller");
      error(kErrInvalidParameter);
      break;
  }
}

// GetID second response (psx-spx "GetID"): no disc, audio disc, or licensed data disc with
// its region letter from the licence text in system-area sector 4.
Cdrom::Response Cdrom::getid_response() const {
  if (!disc_) return make(5, {0x08, 0x40, 0, 0, 0, 0, 0, 0});
  if (disc_->tracks().front().type == disc::TrackType::Audio) return make(5, {0x0A, 0x90, 0, 0, 0, 0, 0, 0});
  u8 region = 'A';
  disc::RawSector s;
  if (disc_->read_sector(disc::kLeadInSectors + 4, s)) {
    std::string text;
    for (u32 i = disc::kMode2DataOffset; i < disc::kMode2DataOffset + 128; ++i)
      if (s[i] != ' ') text += static_cast<char>(s[i]);
    if (text.find("Europe") != std::string::npos) region = 'E';
    else if (text.find("Inc.") != std::string::npos) region = 'I';
  }
  return make(2, {stat(), 0x00, 0x20, 0x00, 'S', 'C', 'E', region});
}

void Cdrom::second_event(Cycles) {
  Second kind = second_;
  second_ = Second::None;
  switch (kind) {
    case Second::None:
      deliver(make(5, {static_cast<u8>(stat() | kStatError), kErrInvalidCommand}));  // SetSession past the last
      break;
    case Second::GetId: {
      Response r = getid_response();
      if (r.irq == 5) motor_on_ = false;
      deliver(r);
      break;
    }
    case Second::MotorOn:
      motor_on_ = disc_ != nullptr;
      deliver(make(2, {stat()}));
      break;
    case Second::Stop:
      motor_on_ = false;
      deliver(make(2, {stat()}));
      break;
    case Second::ReadToc:
    case Second::Init:
    case Second::Pause:
    case Second::SetSession:
      deliver(make(2, {stat()}));
      break;
  }
}

}  // namespace psx
