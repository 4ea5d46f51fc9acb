// Save-state container: a versioned header naming what the state belongs to (BIOS and program
// identities), a checksum of the payload, and the payload (the console's do_state), optionally
// zlib-compressed. docs/save-states.md describes the format and its versions. Layout, little-endian:
//   0 "PSXRLSAV"  8 u32 format version  12 u32 flags (bit 0: compressed)
//   16 u64 BIOS hash (0 = HLE kernel)  24 u64 program hash (EXE or disc)
//   32 u64 payload size  40 u64 payload FNV-1a  48 u64 stored size  56 stored payload
#pragma once
#include <vector>

#include "core/types.h"

namespace psx {

struct SaveStateHeader {
  // 2: sections carry their byte length, scheduler events are saved by name. 1 is still read.
  static constexpr u32 kFormatVersion = 2;
  static constexpr u32 kOldestFormatVersion = 1;
  static constexpr size_t kSize = 56;
  u32 version = kFormatVersion;
  bool compressed = false;
  u64 bios_hash = 0;
  u64 program_hash = 0;
};

// Wraps a payload in the container.
std::vector<u8> pack_save_state(const SaveStateHeader& h, const std::vector<u8>& payload);
// Checks the container against the running console's identities and returns the payload; its
// format version (which StateIO needs to read the payload) goes to *format when given. Throws
// StateError naming what is wrong (truncated, not a save state, unknown version, other BIOS or
// program, corrupt).
std::vector<u8> unpack_save_state(const u8* data, size_t size, u64 bios_hash, u64 program_hash,
                                  u32* format = nullptr);

}  // namespace psx
