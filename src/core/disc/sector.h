// CD-ROM sector format (psx-spx "CDROM Sector Encoding", ECMA-130): the 2352-byte raw sector with
// its 12-byte sync pattern, 4-byte header (BCD minute/second/sector, mode), the Mode 2 XA
// subheader, and the error detection/correction fields (EDC: CRC-32 over the user data; ECC: the
// P and Q Reed-Solomon parity). Shared by the disc readers, the drive and the disc builder.
#pragma once
#include <array>

#include "core/types.h"

namespace psx::disc {

constexpr u32 kRawSectorSize = 2352;
constexpr u32 kDataSectorSize = 2048;
constexpr u32 kSectorsPerSecond = 75;
// Absolute sector numbers count from MSF 00:00:00; the first track's data starts after the
// 2-second lead-in pregap, at 00:02:00 (logical block 0 of the ISO 9660 volume).
constexpr u32 kLeadInSectors = 150;

using RawSector = std::array<u8, kRawSectorSize>;

// Offsets inside a raw sector.
constexpr u32 kHeaderOffset = 12;      // minute, second, sector (BCD), mode
constexpr u32 kSubheaderOffset = 16;   // Mode 2: file, channel, submode, coding info (twice)
constexpr u32 kMode2DataOffset = 24;   // Mode 2 user data
constexpr u32 kMode1DataOffset = 16;   // Mode 1 user data

// XA subheader submode bits (psx-spx "CDROM XA Subheader").
constexpr u8 kSubmodeEor = 0x01;
constexpr u8 kSubmodeVideo = 0x02;
constexpr u8 kSubmodeAudio = 0x04;
constexpr u8 kSubmodeData = 0x08;
constexpr u8 kSubmodeTrigger = 0x10;
constexpr u8 kSubmodeForm2 = 0x20;
constexpr u8 kSubmodeRealtime = 0x40;
constexpr u8 kSubmodeEof = 0x80;

inline u8 to_bcd(u32 v) { return static_cast<u8>((v / 10) << 4 | (v % 10)); }
inline u32 from_bcd(u8 v) { return (v >> 4) * 10 + (v & 0x0F); }
inline bool valid_bcd(u8 v) { return (v >> 4) < 10 && (v & 0x0F) < 10; }

struct Msf {
  u8 minute = 0, second = 0, sector = 0;  // binary, not BCD
  static Msf from_sectors(u32 abs) {
    return {static_cast<u8>(abs / (60 * kSectorsPerSecond)), static_cast<u8>(abs / kSectorsPerSecond % 60),
            static_cast<u8>(abs % kSectorsPerSecond)};
  }
  u32 to_sectors() const { return (minute * 60u + second) * kSectorsPerSecond + sector; }
};

// The sync pattern 00 FF*10 00 that starts every data sector.
bool has_sync(const u8* raw);

// CRC-32 with the CD-ROM EDC polynomial 0x8001801B (bit-reflected, initial value 0).
u32 edc(const u8* data, size_t len);

// Fills sync and header of a data sector at absolute sector `abs` with the given mode byte.
void write_sync_header(u8* raw, u32 abs, u8 mode);

// Completes a Mode 2 Form 1 sector whose sync/header/subheader (both copies) and 2048 data bytes
// are in place: EDC over subheader+data, then P/Q ECC computed with the header taken as zero
// (Mode 2 excludes the header from the ECC so the sector can be relocated).
void finish_mode2_form1(u8* raw);
// Completes a Mode 2 Form 2 sector (2324 data bytes): the EDC at the end of the sector.
void finish_mode2_form2(u8* raw);
// Completes a Mode 1 sector: EDC over sync+header+data, zero field, ECC including the header.
void finish_mode1(u8* raw);

// Builds a complete Mode 2 Form 1 sector at `abs` with the given subheader and 2048 bytes of data.
void build_mode2_form1(u8* raw, u32 abs, const u8 subheader[4], const u8* data2048);

}  // namespace psx::disc
