// PS-X EXE files (psx-spx "CDROM File Formats: PS-X EXE"): header parsing and validation, and
// loading the text into RAM the way the BIOS's Exec() does.
#pragma once
#include <string>
#include <vector>

#include "core/types.h"

namespace psx {

struct PsxExe {
  u32 pc = 0, gp = 0;
  u32 text_addr = 0, text_size = 0;
  u32 bss_addr = 0, bss_size = 0;
  u32 stack_base = 0, stack_offset = 0;
  std::vector<u8> text;

  static constexpr u32 kHeaderSize = 0x800;
  static constexpr u32 kDefaultStack = 0x801FFFF0;

  // Validates every field a loader relies on; throws InputError naming the field and offset.
  static PsxExe parse(const std::vector<u8>& file, const std::string& name);
};

}  // namespace psx
