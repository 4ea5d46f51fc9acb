// The CD-ROM controller (psx-spx "CDROM Controller I/O Ports", "CDROM Commands"): the banked
// registers at 0x1F801800-0x1F801803 (index/status, command/parameter/response/data FIFOs,
// interrupt enable/flag with INT1-INT5), DMA channel 3, the drive mechanics (seek, read, play)
// timed on the scheduler, XA-ADPCM and CD-DA audio pushed to the SPU's CD input FIFO.
// Register access lives in cdrom.cpp, command handling in cdrom_commands.cpp, the drive in
// cdrom_drive.cpp.
#pragma once
#include <algorithm>
#include <array>
#include <functional>
#include <memory>
#include <string>

#include "core/audio_fifo.h"
#include "core/cdrom/xa_adpcm.h"
#include "core/disc/disc.h"
#include "core/io_device.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "core/state.h"

namespace psx {

class Cdrom final : public IoDevice, public DmaPort {
 public:
  static constexpr u32 kBase = 0x1F801800;
  // Bus::map_io works in 16-byte slots; the four registers repeat inside the slot.
  static constexpr u32 kMapSize = 16;

  // Status byte bits (psx-spx "CDROM Status Byte").
  static constexpr u8 kStatError = 0x01;
  static constexpr u8 kStatMotor = 0x02;
  static constexpr u8 kStatSeekError = 0x04;
  static constexpr u8 kStatIdError = 0x08;
  static constexpr u8 kStatShellOpen = 0x10;
  static constexpr u8 kStatRead = 0x20;
  static constexpr u8 kStatSeek = 0x40;
  static constexpr u8 kStatPlay = 0x80;

  // Setmode bits.
  static constexpr u8 kModeCdda = 0x01;
  static constexpr u8 kModeAutoPause = 0x02;
  static constexpr u8 kModeReport = 0x04;
  static constexpr u8 kModeXaFilter = 0x08;
  static constexpr u8 kModeSectorSize = 0x20;  // 0 = 0x800 data bytes, 1 = 0x924 bytes from the header
  static constexpr u8 kModeXaAdpcm = 0x40;
  static constexpr u8 kModeDoubleSpeed = 0x80;

  // Error codes of the second response byte after INT5 (psx-spx "CDROM - Response/Error").
  static constexpr u8 kErrInvalidParameter = 0x10;
  static constexpr u8 kErrParameterCount = 0x20;
  static constexpr u8 kErrInvalidCommand = 0x40;
  static constexpr u8 kErrNotReady = 0x80;  // lid open / no disc / not possible now

  Cdrom(Scheduler& sched, InterruptController& irq);

  // nullptr = an empty drive with the lid closed.
  void insert_disc(std::unique_ptr<disc::Disc> d);
  void set_lid_open(bool open);
  disc::Disc* disc() const { return disc_.get(); }
  // 44.1 kHz stereo CD audio (CD-DA and XA-ADPCM, after the volume matrix) for the SPU's CD input.
  AudioFifo& audio_out() { return audio_; }

  u32 io_read(u32 offset, u32 width) override;
  void io_write(u32 offset, u32 value, u32 width) override;
  void dma_write(const u32* words, u32 count) override;
  void dma_read(u32* words, u32 count) override;
  bool dma_request() const override { return data_pos_ < data_size_; }

  void do_state(StateIO& s);

  std::function<void(const std::string&)> on_log;

  // Timing in CPU cycles: psx-spx "CDROM - Response Timings" averages (measured on a PSone).
  // First responses: GetStat's, which "most other commands" share; Init's, which ReadTOC shares.
  static constexpr Cycles kFirstResponse = 0xC4E1;
  static constexpr Cycles kFirstResponseStopped = 0x5CF4;  // motor off
  static constexpr Cycles kFirstResponseInit = 0x13CCE;
  // The acknowledge (first response) times vary from command to command on hardware: ps1-tests
  // cdrom/timing measured Init's at 69,456 to 93,696 cycles (average 75,086) and GetStat's, with
  // the motor on, at 24,024 to 137,104 (average 45,993). Each first response here draws its time
  // from a uniform range with the measured minimum and average, by a deterministic generator in
  // the state (xorshift32), so the same program always sees the same times.
  static constexpr Cycles kAckInitMin = 69456, kAckInitSpan = 2 * (75086 - 69456);
  static constexpr Cycles kAckMin = 24024, kAckSpan = 2 * (45993 - 24024);
  static constexpr u32 kAckSeed = 0x2545F491;
  // Second responses.
  static constexpr Cycles kGetIdSecond = 0x4A00;
  static constexpr Cycles kPauseSingle = 0x21181C;
  static constexpr Cycles kPauseDouble = 0x10BD93;
  static constexpr Cycles kPauseWhenPaused = 0x1DF2;
  static constexpr Cycles kStopSingle = 0xD38ACA;
  static constexpr Cycles kStopDouble = 0x18A6076;
  static constexpr Cycles kStopWhenStopped = 0x1D7B;
  // psx-spx: the spin-up, SetSession and ReadTOC second-response times are unknown ("probably
  // quite complicated"). These are the project's deterministic estimates: a quarter-second
  // spin-up, half a second to read the TOC, and the gap between a queued response's acknowledge
  // and its delivery.
  static constexpr Cycles kReadTocTime = kCpuClockHz / 2;
  static constexpr Cycles kMotorSpinUp = kCpuClockHz / 4;
  static constexpr Cycles kSetSessionTime = 192000;
  static constexpr Cycles kAckToNextIrq = 1500;
  // INT1 rate: SystemClock * 930h / 4 / 44100 Hz = 451584 cycles per sector at single speed, half
  // at double speed (psx-spx "INT1 Rate"), i.e. 75 and 150 sectors per second.
  static Cycles sector_period(bool double_speed) { return kCpuClockHz / (double_speed ? 150 : 75); }
  // Seek time, which psx-spx does not give: Mednafen's model (PS_CDC::CalcSeekTime), tuned
  // against hardware tests. The head moves at one 72-minute disc (324000 sectors) per second,
  // taking at least kSeekMin; a seek of kSledSeekSectors (30 seconds of disc) or more moves the
  // sled and takes 300 ms more; a shorter one from Pause (motor on, drive idle) waits
  // kResumeFromPause (about 37 ms) at double speed, twice that at single speed.
  static constexpr Cycles kSeekMin = 20000;
  static constexpr u32 kSectorsPerDisc = 72 * 60 * 75;
  static constexpr u32 kSledSeekSectors = 30 * 75;
  static constexpr Cycles kSledSeek = kCpuClockHz * 3 / 10;
  static constexpr Cycles kResumeFromPause = 1237952;
  static Cycles seek_time(u32 from, u32 to, bool paused, bool double_speed) {
    const u32 distance = from > to ? from - to : to - from;
    Cycles t = std::max<Cycles>(Cycles(distance) * kCpuClockHz / kSectorsPerDisc, kSeekMin);
    if (distance >= kSledSeekSectors) t += kSledSeek;
    else if (paused) t += kResumeFromPause * (double_speed ? 1 : 2);
    return t;
  }

 private:
  Cycles first_response_time(u8 command);
  enum class Drive : u8 { Idle, Seeking, Reading, Playing };
  enum class AfterSeek : u8 { None, Read, Play, SeekDone };
  // Second responses that depend on the drive's state when they arrive.
  enum class Second : u8 { None, GetId, ReadToc, Init, MotorOn, Stop, Pause, SetSession };

  struct Response {
    u8 irq = 0;  // INT1..INT5
    u8 size = 0;
    std::array<u8, 16> bytes{};
  };

  // cdrom.cpp: registers and interrupt delivery.
  u8 status_register() const;
  void write_request(u8 v);
  void write_ack(u8 v);
  void deliver(const Response& r);
  void deliver_queued(Cycles late);
  u8 read_data_byte();
  Response make(u8 irq, std::initializer_list<u8> bytes) const;
  void log(const std::string& what);

  // cdrom_commands.cpp
  void command_event(Cycles late);
  void execute(u8 cmd);
  bool check_params(u8 cmd);
  void error(u8 code);
  void second_event(Cycles late);
  void schedule_second(Second kind, Cycles delay);
  Response getid_response() const;
  void cmd_setloc();
  void cmd_play();
  void cmd_read();
  void cmd_seek();
  void cmd_gettd();
  void cmd_getlocp();
  void cmd_test();

  // cdrom_drive.cpp
  u8 stat() const;
  void start_seek(u32 target, AfterSeek then);
  void stop_drive();
  void drive_event(Cycles late);
  void read_tick();
  void play_tick();
  void deliver_data_sector(const disc::RawSector& s);
  void push_xa(const disc::RawSector& s);
  void push_audio(const StereoSample* frames, u32 n);
  Response report_response(const disc::RawSector& s) const;

  Scheduler& sched_;
  InterruptController& irq_;
  AudioFifo audio_;
  std::unique_ptr<disc::Disc> disc_;
  XaAdpcm xa_;
  Scheduler::Handle ev_command_, ev_second_, ev_drive_, ev_deliver_;

  // Host interface.
  u8 index_ = 0;
  std::array<u8, 16> params_{};
  u8 param_count_ = 0;
  Response response_;
  u8 response_pos_ = 0;
  u8 int_enable_ = 0;
  u8 int_flag_ = 0;
  bool busy_ = false;
  u8 command_ = 0;
  Response queued_;  // waits for the CPU to acknowledge the current interrupt
  bool has_queued_ = false;
  Second second_ = Second::None;

  // Sector buffer of the last data sector, and the data FIFO the CPU/DMA drains.
  std::array<u8, disc::kRawSectorSize> sector_{};
  u32 sector_size_ = 0;
  bool sector_ready_ = false;
  std::array<u8, disc::kRawSectorSize> data_{};
  u32 data_size_ = 0;
  u32 data_pos_ = 0;

  // Drive.
  Drive drive_ = Drive::Idle;
  AfterSeek after_seek_ = AfterSeek::None;
  bool motor_on_ = false;
  bool lid_open_ = false;
  bool shell_open_latch_ = false;
  u8 mode_ = 0;
  u32 position_ = disc::kLeadInSectors;  // absolute sector under the head
  u32 setloc_ = disc::kLeadInSectors;
  u32 seek_target_ = disc::kLeadInSectors;
  bool setloc_pending_ = false;
  u8 filter_file_ = 0, filter_channel_ = 0;
  bool muted_ = false;
  s8 scan_ = 0;  // Forward (+1) / Backward (-1) while playing
  std::array<u8, 8> last_header_{};  // header + subheader of the last data sector (GetlocL)
  bool xa_active_ = false;

  // Audio volume matrix (CD L/R -> SPU L/R), written pending and applied with bit 5 of 3.3.
  std::array<u8, 4> volume_pending_{0x80, 0, 0x80, 0};  // LL, LR, RR, RL
  std::array<u8, 4> volume_{0x80, 0, 0x80, 0};
  bool adpcm_muted_ = false;
  u32 ack_random_ = kAckSeed;  // xorshift32 state for the acknowledge times
};

}  // namespace psx
