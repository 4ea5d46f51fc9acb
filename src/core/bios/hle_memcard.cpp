// HLE kernel: the memory cards (psx-spx "BIOS Memory Card Functions", "Memory Card Data
// Format"): the "bu00:"/"bu10:" file device over the card's directory (frames 1-15 of block 0,
// one per 8 KiB block: allocation state, file size, next block, name, XOR checksum) and the
// low-level calls InitCARD2/StartCARD2/StopCARD2, _bu_init, _card_info/_card_load, _card_read/
// _card_write, _new_card, _card_status/_card_wait, _card_auto, card_write_test, _card_chan, the
// find mode and the bufs_cb_* callbacks, and the directory edits of rename, undelete and
// format. The kernel reads and writes the emulated card's sectors directly
// (core/sio/memory_card.h), so every access completes within the call; the events it would
// deliver on completion are delivered before it returns: F0000011h (the hardware I/O) and, for
// _card_info and asynchronous file reads/writes, F4000001h and the handle's own class (psx-spx
// "Event Summary").
#include <cstring>

#include "core/bios/hle_bios.h"
#include "core/sio/memory_card.h"

namespace psx {

namespace {
constexpr u32 kA0 = 0xA0, kC0 = 0xC0;
constexpr u32 kRegA0 = 4, kRegA1 = 5, kRegA2 = 6;
constexpr u32 kFrame = MemoryCard::kSectorSize;
constexpr u32 kBlocks = 15, kFramesPerBlock = 64, kBlockBytes = kFrame * kFramesPerBlock;
// Directory frame fields and allocation states.
constexpr u32 kState = 0x00, kSize = 0x04, kNext = 0x08, kName = 0x0A, kNameLength = 20, kChecksum = 0x7F;
constexpr u32 kFirst = 0x51, kMiddle = 0x52, kLast = 0x53, kFreeMask = 0xA0, kNoNext = 0xFFFF;
constexpr u32 kDeleted = 0xA1 - kFirst;  // 51h-53h become A1h-A3h when erased
constexpr u32 kCreate = 0x200, kAsync = 0x8000;  // open's access mode bits
constexpr u32 kHwCard = 0xF0000011, kSwCard = 0xF4000001;
constexpr u32 kDone = 0x0004, kTimeout = 0x0100, kNewCard = 0x2000;
constexpr u32 kStatusReady = 0x01, kStatusNoCard = 0x11;

u32 le32(const u8* p) { return p[0] | p[1] << 8 | p[2] << 16 | static_cast<u32>(p[3]) << 24; }

// One directory frame as read from the card.
struct Frame {
  std::array<u8, kFrame> b{};
  u32 state() const { return le32(&b[kState]); }
  u32 size() const { return le32(&b[kSize]); }
  u32 next() const { return b[kNext] | b[kNext + 1] << 8; }
  std::string name() const {
    std::string s;
    for (u32 i = 0; i < kNameLength && b[kName + i]; ++i) s += static_cast<char>(b[kName + i]);
    return s;
  }
  void set32(u32 at, u32 v) {
    for (u32 i = 0; i < 4; ++i) b[at + i] = static_cast<u8>(v >> (8 * i));
  }
};

Frame read_frame(const MemoryCard& card, u32 index) {
  Frame f;
  std::memcpy(f.b.data(), &card.data()[(index + 1) * kFrame], kFrame);
  return f;
}

// Writes a block 0 sector with its XOR checksum in byte 7Fh.
void write_sealed(MemoryCard& card, u32 sector, Frame& f) {
  u8 x = 0;
  for (u32 i = 0; i < kChecksum; ++i) x ^= f.b[i];
  f.b[kChecksum] = x;
  card.write_sector(sector, f.b.data());
}

void write_frame(MemoryCard& card, u32 index, Frame& f) { write_sealed(card, index + 1, f); }

bool formatted(const MemoryCard& card) { return card.data()[0] == 'M' && card.data()[1] == 'C'; }

// The directory index of the first block of the file whose name matches, or kBlocks: a file in
// use (state 51h) or, for undelete and find mode 1, a deleted one (A1h).
u32 find_file(const MemoryCard& card, const std::string& name, u32 state = kFirst) {
  for (u32 i = 0; i < kBlocks; ++i) {
    Frame f = read_frame(card, i);
    if (f.state() == state && !f.name().empty() && hle_name_matches(f.name(), name)) return i;
  }
  return kBlocks;
}
}  // namespace

// open on a card: an existing file, or with bit 9 a new one of bits 16-31 blocks, allocated from
// the free blocks in directory order and linked through the next-block fields.
u32 HleBios::card_open(u32 port, const std::string& name, u32 mode, HleFile& f) {
  MemoryCard* card = card_at ? card_at(static_cast<int>(port)) : nullptr;
  if (!card || !formatted(*card)) return kEIo;
  u32 first = find_file(*card, name);
  if (mode & kCreate) {
    if (first != kBlocks) return kEExist;
    const u32 blocks = mode >> 16;
    std::vector<u32> free;
    for (u32 i = 0; i < kBlocks; ++i)
      if ((read_frame(*card, i).state() & 0xF0) == kFreeMask) free.push_back(i);
    if (blocks == 0 || blocks > free.size()) return kENoSpc;
    for (u32 k = 0; k < blocks; ++k) {
      Frame fr;
      fr.set32(kState, k == 0 ? kFirst : k + 1 == blocks ? kLast : kMiddle);
      fr.set32(kSize, k == 0 ? blocks * kBlockBytes : 0);
      const u32 next = k + 1 < blocks ? free[k + 1] : kNoNext;
      fr.b[kNext] = static_cast<u8>(next), fr.b[kNext + 1] = static_cast<u8>(next >> 8);
      if (k == 0)
        for (u32 i = 0; i < kNameLength && i < name.size(); ++i) fr.b[kName + i] = static_cast<u8>(name[i]);
      write_frame(*card, free[k], fr);
    }
    first = free[0];
  }
  if (first == kBlocks) return kENoEnt;
  f.first = first;
  f.size = read_frame(*card, first).size();
  return 0;
}

// read/write on a card: whole 80h-byte sectors from a sector-aligned pointer inside the file
// (psx-spx "File Header, Filesize, and Sector Alignment"), following the block chain.
u32 HleBios::card_transfer(HleFile& f, u32 addr, u32 len, bool write) {
  MemoryCard* card = card_at ? card_at(static_cast<int>(f.port)) : nullptr;
  if (!card) return file_fail(&f, kEIo);
  if ((f.pos % kFrame) || (len % kFrame) || f.pos >= f.size) return file_fail(&f, kEInval);
  const u32 n = std::min(len, f.size - f.pos);
  for (u32 done = 0; done < n; done += kFrame) {
    const u32 rel = (f.pos + done) / kFrame;
    u32 block = f.first;
    for (u32 hop = 0; hop < rel / kFramesPerBlock && block < kBlocks; ++hop) block = read_frame(*card, block).next();
    if (block >= kBlocks) return file_fail(&f, kEIo);
    card_sector(f.port, (block + 1) * kFramesPerBlock + rel % kFramesPerBlock, addr + done, write);
  }
  f.pos += n;
  if (!(f.mode & kAsync)) return n;
  // Asynchronous access: the call returns 0 and completion is an event of the handle's class.
  deliver_event(static_cast<u32>(&f - io_.files.data()), kDone);
  deliver_event(kSwCard, kDone);
  return 0;
}

// erase: the file's blocks become "deleted" (A1h first, A2h middle, A3h last), which undelete
// could restore; the data stays.
bool HleBios::card_erase(u32 port, const std::string& name) {
  MemoryCard* card = card_at ? card_at(static_cast<int>(port)) : nullptr;
  if (!card || !formatted(*card)) return false;
  u32 block = find_file(*card, name);
  if (block == kBlocks) return false;
  for (u32 guard = 0; block < kBlocks && guard < kBlocks; ++guard) {
    Frame f = read_frame(*card, block);
    f.set32(kState, f.state() + kDeleted);
    write_frame(*card, block, f);
    block = f.next();
  }
  return true;
}

// firstfile2/nextfile on a card: files in directory order, attribute 50h, the first sector of
// the file's first block; in find mode 1 (C0h:1Ah) the deleted files instead, attribute A0h.
std::vector<HleBios::DirEntry> HleBios::card_entries(u32 port) {
  std::vector<DirEntry> out;
  MemoryCard* card = card_at ? card_at(static_cast<int>(port)) : nullptr;
  if (!card || !formatted(*card)) return out;
  const u32 state = io2_.card_find_mode ? kFirst + kDeleted : kFirst;
  for (u32 i = 0; i < kBlocks; ++i) {
    Frame f = read_frame(*card, i);
    if (f.state() == state && !f.name().empty())
      out.push_back({f.name(), f.state() & 0xF0, f.size(), (i + 1) * kFramesPerBlock});
  }
  return out;
}

// rename on a card: the file's first directory frame gets the new name (psx-spx "rename"); the
// new name must not be in use.
u32 HleBios::card_rename(u32 port, const std::string& from, const std::string& to) {
  MemoryCard* card = card_at ? card_at(static_cast<int>(port)) : nullptr;
  if (!card || !formatted(*card)) return kEIo;
  if (find_file(*card, to) != kBlocks) return kEExist;
  const u32 block = find_file(*card, from);
  if (block == kBlocks) return kENoEnt;
  Frame f = read_frame(*card, block);
  for (u32 i = 0; i < kNameLength; ++i) f.b[kName + i] = i < to.size() ? static_cast<u8>(to[i]) : 0;
  write_frame(*card, block, f);
  return 0;
}

// undelete: a deleted file's blocks (A1h-A3h along its chain) are in use again (51h-53h), unless
// a block was reused since or a file of that name exists.
u32 HleBios::card_undelete(u32 port, const std::string& name) {
  MemoryCard* card = card_at ? card_at(static_cast<int>(port)) : nullptr;
  if (!card || !formatted(*card)) return kEIo;
  const u32 first = find_file(*card, name, kFirst + kDeleted);
  if (first == kBlocks) return kENoEnt;
  if (find_file(*card, read_frame(*card, first).name()) != kBlocks) return kEExist;
  std::vector<u32> chain;
  for (u32 b = first; b < kBlocks && chain.size() < kBlocks; b = read_frame(*card, b).next()) {
    const u32 state = read_frame(*card, b).state();
    if (state < kFirst + kDeleted || state > kLast + kDeleted) return kENoEnt;
    chain.push_back(b);
  }
  for (u32 b : chain) {
    Frame f = read_frame(*card, b);
    f.set32(kState, f.state() - kDeleted);
    write_frame(*card, b, f);
  }
  return 0;
}

// format: block 0 as a freshly formatted card holds it (psx-spx "Memory Card Data Format"): the
// "MC" header, 15 free directory frames (A0h, no next block), an empty broken sector list
// (FFFFFFFFh), FFh-filled replacement and unused frames, and the write test frame = the header.
// The file blocks keep their data.
u32 HleBios::card_format(u32 port) {
  MemoryCard* card = card_at ? card_at(static_cast<int>(port)) : nullptr;
  if (!card) return kEIo;
  constexpr u32 kReplacement = 36, kWriteTest = 63;  // frames 16-35 are the broken sector list
  for (u32 sector = 0; sector < kFramesPerBlock; ++sector) {
    Frame f;
    if (sector == 0 || sector == kWriteTest) {
      f.b[0] = 'M', f.b[1] = 'C';
    } else if (sector <= kBlocks) {
      f.set32(kState, kFreeMask);
      f.b[kNext] = f.b[kNext + 1] = 0xFF;
    } else if (sector < kReplacement) {
      f.set32(0, 0xFFFFFFFF);
    } else {
      f.b.fill(0xFF);
      card->write_sector(sector, f.b.data());
      continue;
    }
    write_sealed(*card, sector, f);
  }
  return 0;
}

// One raw sector between RAM and the card; false when the slot is empty.
bool HleBios::card_sector(u32 port, u32 sector, u32 addr, bool write) {
  MemoryCard* card = card_at ? card_at(static_cast<int>(port)) : nullptr;
  if (!card || sector >= MemoryCard::kSectors) return false;
  u8 buf[kFrame];
  if (write) {
    for (u32 i = 0; i < kFrame; ++i) buf[i] = peek8(addr + i);
    card->write_sector(sector, buf);
  } else {
    for (u32 i = 0; i < kFrame; ++i) poke8(addr + i, card->data()[sector * kFrame + i]);
  }
  return true;
}

// The completion events of a low-level access: done, no card (timeout), or for _card_info a card
// not yet written since it was inserted (FLAG bit 3, "new card").
void HleBios::card_deliver(u32 port, bool info) {
  MemoryCard* card = card_at ? card_at(static_cast<int>(port)) : nullptr;
  u32 spec = !card ? kTimeout : info && (card->flag() & MemoryCard::kFlagFresh) ? kNewCard : kDone;
  io_.card_status[port] = card ? kStatusReady : kStatusNoCard;
  io2_.card_last_port = port << 4;
  deliver_event(kHwCard, spec);
  if (info) deliver_event(kSwCard, spec);
}

bool HleBios::card_call(u32 table, u32 fn) {
  const u32 a0 = cpu_.reg(kRegA0);
  if (table == kC0) {
    switch (fn) {
      case 0x1A: io2_.card_find_mode = a0 & 1; return_to_caller(0); return true;  // set_card_find_mode
      case 0x1D: return_to_caller(io2_.card_find_mode); return true;             // get_card_find_mode
      default: return false;
    }
  }
  return table == kA0 ? card_call_a0(fn) : card_call_b0(fn);
}

// A "port" argument is 00h (slot 1) or 10h (slot 2).
bool HleBios::card_call_a0(u32 fn) {
  const u32 a0 = cpu_.reg(kRegA0), port = (a0 >> 4) & 1;
  switch (fn) {
    case 0x55:
    case 0x70: return_to_caller(0); return true;  // _bu_init: the directory is read on use
    case 0xAB:                                     // _card_info(port)
    case 0xAC:                                     // _card_load(port)
      card_deliver(port, true);
      return_after_events(1);
      return true;
    case 0xAD: io_.card_auto_format = a0; return_to_caller(0); return true;  // _card_auto
    // bufs_cb_0..4: the card driver's completion callbacks move the file functions' pending
    // access along; every access here completes inside its call, so none is pending and they
    // do nothing (as a BIOS's do with no operation under way).
    case 0xA7:
    case 0xA8:
    case 0xA9:
    case 0xAA:
    case 0xAE: return_to_caller(0); return true;
    case 0xAF: {  // card_write_test(port): rewrites sector 3Fh, which clears the new-card flag
      MemoryCard* card = card_at ? card_at(static_cast<int>(port)) : nullptr;
      if (card) card->write_sector(0x3F, &card->data()[0x3F * kFrame]);
      card_deliver(port, false);
      return_after_events(1);
      return true;
    }
    default: return false;
  }
}

bool HleBios::card_call_b0(u32 fn) {
  const u32 a0 = cpu_.reg(kRegA0), a1 = cpu_.reg(kRegA1), a2 = cpu_.reg(kRegA2), port = (a0 >> 4) & 1;
  switch (fn) {
    case 0x4A: {  // InitCARD2(pad_enable): returns whether it ran before
      u32 before = io_.card_status[0] != 0;
      io_.card_status = {kStatusReady, kStatusReady};
      return_to_caller(before);
      return true;
    }
    case 0x4B: io_.card_started = 1; return_to_caller(1); return true;  // StartCARD2
    case 0x4C: io_.card_started = 0; return_to_caller(1); return true;  // StopCARD2
    case 0x4D: card_deliver(port, true); return_after_events(1); return true;  // _card_info_subfunc
    case 0x4E:                                                                 // _card_write
    case 0x4F: {                                                               // _card_read
      if (a1 > MemoryCard::kSectors) {  // sector 400h is accepted (psx-spx: "probably a BUG")
        return_to_caller(0);
        return true;
      }
      card_sector(port, a1, a2, fn == 0x4E);
      card_deliver(port, false);
      return_after_events(1);
      return true;
    }
    case 0x50: return_to_caller(0); return true;  // _new_card: the new-card flag never blocks here
    case 0x58: return_to_caller(io2_.card_last_port); return true;  // _card_chan: 00h/10h
    case 0x5C:                                    // _card_status(slot)
    case 0x5D:                                    // _card_wait(slot): nothing is ever busy
      return_to_caller(io_.card_status[a0 & 1] ? io_.card_status[a0 & 1] : kStatusReady);
      return true;
    default: return false;
  }
}

}  // namespace psx
