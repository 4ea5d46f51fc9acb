// Memory Control 1 access timing (psx-spx "Memory Control", 0x1F801008-0x1F801020): how many CPU
// cycles a read from a region on the external bus takes, from the region's Delay/Size register
// (read delay, COM0/COM2/COM3 selects, 8/16-bit data bus) and the COM_DELAY register.
#pragma once
#include <algorithm>

#include "core/types.h"

namespace psx {

// Total cycles of a read of `width` bytes (1, 2 or 4), the load's own issue cycle included.
// psx-spx gives the rule as: FIRST = SEQ = 0, MIN = 0; with COM0 add COM0-1 to both; with COM2 add
// COM2 to both; with COM3 MIN = COM3; FIRST gains 1 while below 6; both gain the read delay + 2;
// then FIRST >= MIN+6 and SEQ >= MIN+2. A wider access than the bus is one FIRST plus a SEQ per
// further 8/16-bit unit. With the BIOS setting 0x0013243F and COM_DELAY 0x00031125 this gives
// 7/13/25 cycles, as JaCzekanski's ps1-tests cpu/access-time measured on hardware.
constexpr u32 memory_read_cycles(u32 delay_size, u32 com_delay, u32 width) {
  const s32 read_delay = static_cast<s32>((delay_size >> 4) & 0xF);
  const s32 com0 = static_cast<s32>(com_delay & 0xF);
  const s32 com2 = static_cast<s32>((com_delay >> 8) & 0xF);
  const s32 com3 = static_cast<s32>((com_delay >> 12) & 0xF);
  s32 first = 0, seq = 0, min = 0;
  if (delay_size & (1u << 8)) {
    first += com0 - 1;
    seq += com0 - 1;
  }
  if (delay_size & (1u << 10)) {
    first += com2;
    seq += com2;
  }
  if (delay_size & (1u << 11)) min = com3;
  if (first < 6) first += 1;
  first += read_delay + 2;
  seq += read_delay + 2;
  first = std::max(first, min + 6);
  seq = std::max(seq, min + 2);
  const u32 bus_bytes = (delay_size & (1u << 12)) ? 2 : 1;
  const u32 units = width > bus_bytes ? width / bus_bytes : 1;
  return static_cast<u32>(first + static_cast<s32>(units - 1) * seq);
}

}  // namespace psx
