// Memory card command protocol, blank-card format and atomic image file handling.
#include "core/sio/memory_card.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "core/atomic_file.h"

namespace psx {

namespace {
constexpr u8 kCmdRead = 0x52;   // "R"
constexpr u8 kCmdWrite = 0x57;  // "W"
constexpr u8 kCmdGetId = 0x53;  // "S"
constexpr u8 kEndGood = 0x47;
constexpr u8 kEndBadChecksum = 0x4E;
constexpr u8 kEndBadSector = 0xFF;

std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

// XOR of bytes 00h..7Eh goes into byte 7Fh of every directory-block frame.
void seal_frame(u8* frame) {
  u8 x = 0;
  for (u32 i = 0; i < MemoryCard::kSectorSize - 1; ++i) x ^= frame[i];
  frame[MemoryCard::kSectorSize - 1] = x;
}
}  // namespace

MemoryCard::MemoryCard() : data_(kSize) { format(); }

MemoryCard::MemoryCard(std::filesystem::path path) : path_(std::move(path)), data_(kSize) {
  std::error_code ec;
  if (std::filesystem::exists(path_, ec))
    load();
  else
    format();
}

MemoryCard::~MemoryCard() {
  try {
    flush();
  } catch (const MemoryCardError& e) {
    std::fprintf(stderr, "%s\n", e.what());
  }
}

// An empty card as the BIOS formats it (psx-spx "Memory Card Data Format"): header frame "MC",
// 15 free directory entries, no broken sectors, FFh-filled spare frames, write-test frame = header.
void MemoryCard::format() {
  std::fill(data_.begin(), data_.end(), 0x00);
  u8* block0 = data_.data();
  auto frame = [&](u32 n) { return block0 + n * kSectorSize; };
  frame(0)[0] = 'M';
  frame(0)[1] = 'C';
  seal_frame(frame(0));
  for (u32 n = 1; n <= 15; ++n) {
    frame(n)[0] = 0xA0;  // free, freshly formatted
    frame(n)[8] = 0xFF;  // no next block
    frame(n)[9] = 0xFF;
    seal_frame(frame(n));
  }
  for (u32 n = 16; n <= 35; ++n) {
    std::memset(frame(n), 0xFF, 4);  // broken sector list entry: none
    seal_frame(frame(n));
  }
  std::memset(frame(36), 0xFF, (63 - 36) * kSectorSize);  // replacement data and unused frames
  std::memcpy(frame(63), frame(0), kSectorSize);
}

void MemoryCard::load() {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path_, ec))
    throw MemoryCardError("memory card " + quoted(path_) + ": not a regular file");
  const auto size = std::filesystem::file_size(path_, ec);
  if (ec)
    throw MemoryCardError("memory card " + quoted(path_) + ": cannot read its size: " + ec.message());
  if (size != kSize)
    throw MemoryCardError("memory card " + quoted(path_) + ": file is " + std::to_string(size) +
                          " bytes, expected exactly " + std::to_string(kSize) +
                          " bytes (a raw 128 KiB card image)");
  std::FILE* f = std::fopen(path_.c_str(), "rb");
  if (!f) throw MemoryCardError("memory card " + quoted(path_) + ": cannot open: " + std::strerror(errno));
  const size_t got = std::fread(data_.data(), 1, kSize, f);
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if (failed || got != kSize)
    throw MemoryCardError("memory card " + quoted(path_) + ": read failed at offset " + std::to_string(got) +
                          " of " + std::to_string(kSize));
}

void MemoryCard::flush() {
  if (!dirty_ || path_.empty()) return;
  try {
    write_file_atomically(path_.string(), data_.data(), kSize);
  } catch (const std::runtime_error& e) {
    throw MemoryCardError(std::string("memory card ") + e.what());
  }
  dirty_ = false;
}

SioDevice::Reply MemoryCard::transfer(u8 command) {
  const u32 step = step_++;
  late_ack_ = false;
  Reply r;
  if (step == 0) {
    mode_ = 0;
    r = {0xFF, true};  // 81h memory card access: dummy reply
  } else if (step == 1) {
    // The FLAG byte answers the command byte; an unknown command ends the transfer (no /ACK).
    const bool known = command == kCmdRead || command == kCmdWrite || command == kCmdGetId;
    mode_ = known ? command : kIgnoring;
    r = {flag_, known};
  } else if (mode_ == kCmdRead) {
    r = read_step(step, command);
  } else if (mode_ == kCmdWrite) {
    r = write_step(step, command);
  } else if (mode_ == kCmdGetId) {
    r = get_id_step(step);
  }
  previous_ = command;
  return r;
}

// Steps 2-5, the same for read and write: card IDs 5Ah 5Dh, then the sector number MSB/LSB
// in (each answered with the byte before it), which also seeds the checksum.
SioDevice::Reply MemoryCard::address_step(u32 step, u8 command) {
  switch (step) {
    case 2: return {0x5A, true};
    case 3: return {0x5D, true};
    case 4:
      sector_ = static_cast<u16>(command << 8);
      return {0x00, true};
    case 5:
      sector_ |= command;
      checksum_ = static_cast<u8>((sector_ >> 8) ^ (sector_ & 0xFF));
      return {previous_, true};
    default: return {0xFF, false};
  }
}

// Read: 5Ah 5Dh, sector MSB/LSB in, 5Ch 5Dh, confirmed address, 128 data bytes, checksum, 47h.
SioDevice::Reply MemoryCard::read_step(u32 step, u8 command) {
  if (step <= 5) return address_step(step, command);
  const bool valid = sector_ < kSectors;
  switch (step) {
    case 6:
      late_ack_ = true;
      return {0x5C, true};
    case 7: return {0x5D, true};
    case 8: return {static_cast<u8>(valid ? sector_ >> 8 : 0xFF), true};
    case 9:
      // Sony cards answer a sector past 3FFh with FFFFh and stop: no data, no /ACK.
      if (!valid) mode_ = kIgnoring;
      return {static_cast<u8>(valid ? sector_ & 0xFF : 0xFF), valid};
    default: break;
  }
  if (step < 10 + kSectorSize) {
    const u8 d = data_[sector_ * kSectorSize + (step - 10)];
    checksum_ ^= d;
    return {d, true};
  }
  if (step == 10 + kSectorSize) return {checksum_, true};
  mode_ = kIgnoring;
  return {kEndGood, false};  // end byte: the last one, so no /ACK
}

// Write: 5Ah 5Dh, sector MSB/LSB, 128 data bytes and checksum in (each answered with the byte
// before it), then 5Ch 5Dh and the end status.
SioDevice::Reply MemoryCard::write_step(u32 step, u8 command) {
  if (step <= 5) return address_step(step, command);
  constexpr u32 kChecksumStep = 6 + kSectorSize;
  if (step < kChecksumStep) {
    sector_buf_[step - 6] = command;
    checksum_ ^= command;
    return {previous_, true};
  }
  if (step == kChecksumStep) {
    commit_write(command);
    return {previous_, true};
  }
  if (step == kChecksumStep + 1) return {0x5C, true};
  if (step == kChecksumStep + 2) return {0x5D, true};
  mode_ = kIgnoring;
  return {end_status_, false};
}

void MemoryCard::commit_write(u8 received_checksum) {
  if (sector_ >= kSectors) {
    end_status_ = kEndBadSector;
    return;
  }
  if (received_checksum != checksum_) {
    end_status_ = kEndBadChecksum;
    return;
  }
  end_status_ = kEndGood;
  write_sector(sector_, sector_buf_.data());
}

void MemoryCard::write_sector(u32 sector, const u8* src) {
  std::memcpy(&data_[sector * kSectorSize], src, kSectorSize);
  flag_ &= static_cast<u8>(~kFlagFresh);
  dirty_ = true;
  // Each written sector reaches the file at once, so a host crash loses at most the sectors of
  // the write in flight. A failing file never stops the emulated card.
  try {
    flush();
  } catch (const MemoryCardError& e) {
    std::fprintf(stderr, "%s\n", e.what());
  }
}

// Get ID: 5Ah 5Dh 5Ch 5Dh 04h 00h 00h 80h (psx-spx; Sony cards only).
SioDevice::Reply MemoryCard::get_id_step(u32 step) {
  static constexpr u8 kId[] = {0x5A, 0x5D, 0x5C, 0x5D, 0x04, 0x00, 0x00, 0x80};
  const u32 i = step - 2;
  if (i >= sizeof(kId)) {
    mode_ = kIgnoring;
    return {};
  }
  return {kId[i], i + 1 < sizeof(kId)};
}

void MemoryCard::do_state(StateIO& s) {
  s.section("MCRD", 1);
  s.bytes(data_.data(), kSize);
  s.pod(flag_);
  s.boolean(dirty_);
  s.pod(step_);
  s.pod(mode_);
  s.pod(sector_);
  s.pod(checksum_);
  s.pod(previous_);
  s.pod(end_status_);
  s.boolean(late_ack_);
  s.pod(sector_buf_);
  // A read goes past step 9 only for a sector on the card (read_step stops it there otherwise),
  // so a state claiming a later step of a read beyond the card is corrupt: reading on would index
  // past the image (found by fuzz/fuzz_memcard.cpp).
  if (s.loading() && mode_ == kCmdRead && step_ >= 10 && sector_ >= kSectors)
    s.fail("memory card: a read of sector " + std::to_string(sector_) + " is in progress, beyond the card's " +
           std::to_string(kSectors) + " sectors");
  s.end_section("MCRD");
}

}  // namespace psx
