// PlayStation memory card (psx-spx "Memory Card Read/Write Commands", "Memory Card Data Format"):
// 128 KiB of 1024 sectors of 128 bytes behind the 81h address byte, with the read (52h), write
// (57h) and get-ID (53h) commands and the FLAG byte. The image may be backed by a file: loaded when
// the card is made, created on the first write command, and always replaced atomically.
#pragma once
#include <array>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "core/sio/sio_device.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

// A memory card file that cannot be used (wrong size, unreadable, unwritable). The message names
// the file and what was expected.
class MemoryCardError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class MemoryCard final : public SioDevice {
 public:
  static constexpr u32 kSectorSize = 128;
  static constexpr u32 kSectors = 1024;
  static constexpr u32 kSize = kSectorSize * kSectors;  // 131072 bytes
  // FLAG bit 3: set at power-up/insertion ("directory not read yet"), cleared by a write.
  static constexpr u8 kFlagFresh = 0x08;
  // IRQ7 comes ~1500 cycles after the start of a byte (psx-spx "Timings"); at the usual 1088-cycle
  // byte time that leaves 412 cycles from the byte's end to /ACK.
  static constexpr Cycles kAckDelay = 412;
  // Original Sony cards delay the /ACK after the 7th byte of a read by ~31000 more cycles.
  static constexpr Cycles kReadLateAckDelay = kAckDelay + 31000;

  // A freshly formatted card that exists only in memory.
  MemoryCard();
  // A card backed by `path`: the file is loaded if it exists (it must be exactly kSize bytes);
  // otherwise the card starts freshly formatted and the file is created by the first write
  // command. Throws MemoryCardError.
  explicit MemoryCard(std::filesystem::path path);
  ~MemoryCard() override;
  MemoryCard(const MemoryCard&) = delete;
  MemoryCard& operator=(const MemoryCard&) = delete;

  Reply transfer(u8 command) override;
  Cycles ack_delay() const override { return late_ack_ ? kReadLateAckDelay : kAckDelay; }
  void deselect() override { step_ = 0; }

  // Writes the image to its file if it changed since the last flush: a temporary file beside it
  // is written and synced, then renamed over the card file, so the file is always either the old
  // or the new image. Throws MemoryCardError (the old file is then left as it was).
  void flush();
  bool dirty() const { return dirty_; }
  const std::filesystem::path& path() const { return path_; }
  const std::vector<u8>& data() const { return data_; }
  // Stores one sector (sector < kSectors) as a completed write command does: clears FLAG bit 3
  // and saves the file. Used by the HLE kernel's card functions, which bypass the serial port.
  void write_sector(u32 sector, const u8* src);
  u8 flag() const { return flag_; }

  void do_state(StateIO& s);

 private:
  static constexpr u8 kIgnoring = 0xFF;  // mode_ after an unknown command or a bad read sector

  void format();
  void load();
  Reply address_step(u32 step, u8 command);
  Reply read_step(u32 step, u8 command);
  Reply write_step(u32 step, u8 command);
  Reply get_id_step(u32 step);
  void commit_write(u8 received_checksum);

  std::filesystem::path path_;  // configuration, not state: empty = no file
  std::vector<u8> data_;
  u8 flag_ = kFlagFresh;
  bool dirty_ = false;  // written since the last successful flush

  // Current command. step_ counts bytes since the 81h address byte (index 0).
  u32 step_ = 0;
  u8 mode_ = 0;  // command byte (52h, 57h, 53h) or kIgnoring
  u16 sector_ = 0;
  u8 checksum_ = 0;    // running XOR of address and data bytes
  u8 previous_ = 0;    // last command byte received (the "pre" replies during a write)
  u8 end_status_ = 0;  // 47h good, 4Eh bad checksum, FFh bad sector
  bool late_ack_ = false;
  std::array<u8, kSectorSize> sector_buf_{};
};

}  // namespace psx
