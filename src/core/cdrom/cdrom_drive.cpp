// The drive mechanics behind the controller: seeking (time grows with distance), reading data
// sectors at 75 or 150 sectors per second (INT1 per sector, XA-ADPCM sectors routed to the SPU
// instead), CD-DA playback with Report/AutoPause, and the status byte that reflects it all.
#include <algorithm>
#include <vector>

#include "core/cdrom/cdrom.h"

namespace psx {

u8 Cdrom::stat() const {
  u8 s = 0;
  if (motor_on_) s |= kStatMotor;
  if (shell_open_latch_ || lid_open_) s |= kStatShellOpen;
  if (drive_ == Drive::Seeking) s |= kStatSeek;
  if (drive_ == Drive::Reading) s |= kStatRead;
  if (drive_ == Drive::Playing) s |= kStatPlay;
  return s;
}

void Cdrom::stop_drive() {
  sched_.cancel(ev_drive_);
  drive_ = Drive::Idle;
  after_seek_ = AfterSeek::None;
  scan_ = 0;
  xa_active_ = false;
}

void Cdrom::start_seek(u32 target, AfterSeek then) {
  sched_.cancel(ev_drive_);
  const bool paused = motor_on_ && drive_ == Drive::Idle;
  Cycles t = seek_time(position_, target, paused, mode_ & kModeDoubleSpeed);
  if (!motor_on_) t += kMotorSpinUp;
  motor_on_ = true;
  drive_ = Drive::Seeking;
  after_seek_ = then;
  seek_target_ = target;
  xa_.reset();
  xa_active_ = false;
  sched_.schedule(ev_drive_, t);
}

void Cdrom::drive_event(Cycles) {
  switch (drive_) {
    case Drive::Idle:
      return;
    case Drive::Seeking:
      if (seek_target_ >= disc_->lead_out()) {
        drive_ = Drive::Idle;
        deliver(make(5, {static_cast<u8>(stat() | kStatError | kStatSeekError), kErrInvalidParameter}));
        return;
      }
      position_ = seek_target_;
      if (after_seek_ == AfterSeek::SeekDone) {
        drive_ = Drive::Idle;
        deliver(make(2, {stat()}));
        return;
      }
      drive_ = after_seek_ == AfterSeek::Play ? Drive::Playing : Drive::Reading;
      break;
    case Drive::Reading:
      read_tick();
      break;
    case Drive::Playing:
      play_tick();
      break;
  }
  if (drive_ == Drive::Reading || drive_ == Drive::Playing)
    sched_.schedule(ev_drive_, sector_period(mode_ & kModeDoubleSpeed));
}

void Cdrom::read_tick() {
  disc::RawSector s;
  if (!disc_->read_sector(position_, s)) {
    if (position_ < disc_->lead_out()) log(disc_->last_error());
    drive_ = Drive::Idle;
    deliver(make(4, {stat()}));  // DataEnd: the head ran past the last sector
    return;
  }
  ++position_;
  // Real-time audio sectors go to the ADPCM decoder when XA-ADPCM is on (never to the CPU); with
  // the XA filter, only the file/channel chosen by Setfilter is played, the rest skipped.
  const u8 submode = s[18];
  bool xa = (mode_ & kModeXaAdpcm) && s[15] == 2 && (submode & disc::kSubmodeAudio) && (submode & disc::kSubmodeRealtime);
  if (xa) {
    if (!(mode_ & kModeXaFilter) || (s[16] == filter_file_ && s[17] == filter_channel_)) push_xa(s);
    return;
  }
  deliver_data_sector(s);
}

void Cdrom::deliver_data_sector(const disc::RawSector& s) {
  if (mode_ & kModeSectorSize) {
    // 0x924 bytes: everything after the sync pattern (header, subheader, data, EDC/ECC).
    std::copy(s.begin() + 12, s.begin() + 12 + 0x924, sector_.begin());
    sector_size_ = 0x924;
  } else {
    u32 off = s[15] == 1 ? disc::kMode1DataOffset : disc::kMode2DataOffset;
    std::copy(s.begin() + off, s.begin() + off + disc::kDataSectorSize, sector_.begin());
    sector_size_ = disc::kDataSectorSize;
  }
  std::copy(s.begin() + 12, s.begin() + 20, last_header_.begin());
  sector_ready_ = true;
  deliver(make(1, {stat()}));
}

void Cdrom::push_audio(const StereoSample* frames, u32 n) {
  for (u32 i = 0; i < n; ++i) {
    StereoSample out{};
    if (!muted_) {
      // Volume matrix: 0x80 = 100%; each output is the sum of both inputs' contributions.
      s32 l = (frames[i].left * volume_[0] + frames[i].right * volume_[3]) >> 7;
      s32 r = (frames[i].left * volume_[1] + frames[i].right * volume_[2]) >> 7;
      out = {static_cast<s16>(std::clamp(l, -32768, 32767)), static_cast<s16>(std::clamp(r, -32768, 32767))};
    }
    audio_.push(out);  // a full FIFO drops frames: the SPU is not consuming
  }
}

void Cdrom::push_xa(const disc::RawSector& s) {
  std::vector<StereoSample> frames;
  xa_.decode_sector(s.data() + disc::kMode2DataOffset, s[19], frames);
  if (adpcm_muted_) std::fill(frames.begin(), frames.end(), StereoSample{});
  push_audio(frames.data(), static_cast<u32>(frames.size()));
  xa_active_ = true;
}

// Report (Setmode bit 2) while playing: INT1 with the position every 10 sectors, absolute time
// at sector 0/20/40/60 of each second, track-relative time (seconds | 0x80) at 10/30/50/70.
Cdrom::Response Cdrom::report_response(const disc::RawSector& s) const {
  const disc::Track* t = disc_->track_at(position_);
  disc::Msf a = disc::Msf::from_sectors(position_);
  bool relative = (a.sector / 10) % 2 == 1;
  disc::Msf m = relative && t ? disc::Msf::from_sectors(position_ >= t->index1 ? position_ - t->index1 : 0) : a;
  u16 peak = 0;
  for (u32 i = 0; i < disc::kRawSectorSize; i += 2)
    peak = std::max<u16>(peak, static_cast<u16>(std::abs(static_cast<s16>(s[i] | s[i + 1] << 8))));
  return make(1, {stat(), static_cast<u8>(t ? disc::to_bcd(t->number) : 0xAA), static_cast<u8>(t && position_ < t->index1 ? 0 : 1),
                  disc::to_bcd(m.minute), static_cast<u8>(disc::to_bcd(m.second) | (relative ? 0x80 : 0)),
                  disc::to_bcd(m.sector), static_cast<u8>(peak), static_cast<u8>(peak >> 8)});
}

void Cdrom::play_tick() {
  disc::RawSector s;
  if (!disc_->read_sector(position_, s)) {
    drive_ = Drive::Idle;
    deliver(make(4, {stat()}));  // end of disc
    return;
  }
  const disc::Track* t = disc_->track_at(position_);
  StereoSample frames[disc::kRawSectorSize / 4] = {};
  // Data tracks and fast scanning play as silence.
  if (t && t->type == disc::TrackType::Audio && scan_ == 0)
    for (u32 i = 0; i < disc::kRawSectorSize / 4; ++i)
      frames[i] = {static_cast<s16>(s[4 * i] | s[4 * i + 1] << 8), static_cast<s16>(s[4 * i + 2] | s[4 * i + 3] << 8)};
  push_audio(frames, disc::kRawSectorSize / 4);
  if ((mode_ & kModeReport) && disc::Msf::from_sectors(position_).sector % 10 == 0) deliver(report_response(s));
  u32 track_end = t ? t->end : disc_->lead_out();
  if (scan_ < 0) position_ = position_ > 8 + disc::kLeadInSectors ? position_ - 8 : disc::kLeadInSectors;
  else position_ += scan_ > 0 ? 8 : 1;
  if ((mode_ & kModeAutoPause) && position_ >= track_end) {
    drive_ = Drive::Idle;
    deliver(make(4, {stat()}));  // AutoPause: end of track
  }
}

}  // namespace psx
