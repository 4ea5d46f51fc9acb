// State of the HLE kernel's file functions (psx-spx "BIOS File Functions", "BIOS CDROM
// Functions", "BIOS Memory Card Functions"): the 16 file handles, the last error number, the
// firstfile/nextfile search, the cdrom: current directory and the memory card driver's status.
// A BIOS keeps these in its FCBs and private RAM; the HLE kernel keeps them here, in the save
// state, because the devices behind them (the disc image, the card image) are read on the host.
#pragma once
#include <array>
#include <string>

#include "core/types.h"

namespace psx {

// Which device an open handle belongs to (the device name before ':' in its path).
enum HleDevice : u32 { kDevNone, kDevTty, kDevCdrom, kDevCard };

// One file handle: the BIOS's FCB reduced to what its functions use.
struct HleFile {
  u32 device = kDevNone;
  u32 port = 0;   // memory card slot: 0 for "bu00:", 1 for "bu10:"
  u32 first = 0;  // cdrom: the file's first logical block; card: its first block's directory index
  u32 size = 0;   // bytes
  u32 pos = 0;    // the file pointer lseek moves
  u32 mode = 0;   // the access mode open was given (bit 15: asynchronous card access)
  u32 error = 0;  // the last error on this handle (_get_error)
};

struct HleIoState {
  static constexpr u32 kHandles = 16;
  std::array<HleFile, kHandles> files{};
  u32 last_error = 0;  // _get_errno
  // firstfile2/nextfile: the device, the directory searched and the name pattern (20 characters,
  // '?' = any one character, as firstfile expands '*').
  u32 find_device = kDevNone, find_port = 0, find_next = 0;
  std::array<char, 64> find_dir{};
  std::array<char, 24> find_pattern{};
  std::array<char, 64> cd_dir{};       // cd("cdrom:\DIR"): the cdrom: current directory
  std::array<u32, 2> card_status{};    // _card_status per slot: 01h ready, 11h no card
  u32 card_started = 0;                // StartCARD2 ran (and StopCARD2 did not since)
  u32 card_auto_format = 0;            // _card_auto
  u32 result_stub = 0;                 // kernel code that sets v0 after event callbacks ran
};

// Added in save-state version 5 (kept apart so version 4 states still load): the memory card
// find mode (C0h:1Ah), the port of the last low-level card access (_card_chan) and the
// asynchronous CD calls' target sector and drive mode.
struct HleIoState2 {
  u32 card_find_mode = 0;  // 0: firstfile2/nextfile list files, 1: deleted files
  u32 card_last_port = 0;  // 00h slot 1, 10h slot 2
  u32 cd_seek_lba = 0;     // CdAsyncSeekL's sector
  u32 cd_mode = 0;         // CdAsyncSetMode/CdAsyncReadSector's Setmode byte
};

// File error numbers (psx-spx "File Error Numbers for B(54h) and B(55h)").
enum HleErrno : u32 {
  kENoEnt = 0x02,   // file not found
  kEBadF = 0x09,    // invalid or unused file handle
  kEIo = 0x10,      // general error (no disc, unformatted card)
  kEExist = 0x11,   // file already exists
  kEXDev = 0x12,    // rename from one device to another
  kENoDev = 0x13,   // unknown device name
  kEInval = 0x16,   // sector alignment error, fpos >= filesize, unknown seek type
  kEMFile = 0x18,   // not enough free file handles
  kENoSpc = 0x1C,   // not enough free memory card blocks
};

// A file name against a search pattern: '?' matches any one character, also a name's end, after
// which the rest of the pattern is ignored (the BIOS bug psx-spx describes: "FILE?.DAT" also
// matches "FILE"); letters match in either case.
bool hle_name_matches(const std::string& name, const std::string& pattern);

}  // namespace psx
