// Memory Control 1 access timing (psx-spx "Memory Control", 0x1F801008-0x1F801020): how many CPU
// cycles a read from a region on the external bus takes, from the region's Delay/Size register
// (read delay, COM0/COM2/COM3 selects, 8/16-bit data bus) and the COM_DELAY register.
#pragma once
#include <algorithm>

#include "core/types.h"

namespace psx {

// Total cycles of a read of `units` units of the region's data bus, the load's own issue cycle
// included: one FIRST bus cycle and a SEQ one per further 8/16-bit unit.
// FIRST = read delay + 4; SEQ = read delay + 2, plus COM0 with the recovery period (bit 8) and
// COM2 with the floating period (bit 10): those periods follow a bus cycle, so they delay the
// next unit of the same access but not the first. psx-spx's rule adds COM0-1 and COM2 to FIRST
// as well, which JaCzekanski's ps1-tests cpu/access-time hardware log contradicts: with the BIOS's
// settings it measured BIOS/EXP1 7/13/25 (8/16/32-bit), EXP3 6/6/10, EXP2 11/26/56, CD-ROM
// 8/14/26 and SPU 18/18/39 cycles, exactly what this gives (COM_DELAY 0x00031125). psx-spx's
// floors stay (no measured setting reaches them): FIRST >= MIN + 6 and SEQ >= MIN + 2, MIN being
// COM3 with the pre-strobe period (bit 11), else 0.
constexpr u32 memory_read_unit_cycles(u32 delay_size, u32 com_delay, u32 units) {
  const s32 read_delay = static_cast<s32>((delay_size >> 4) & 0xF);
  const s32 com0 = static_cast<s32>(com_delay & 0xF);
  const s32 com2 = static_cast<s32>((com_delay >> 8) & 0xF);
  const s32 com3 = static_cast<s32>((com_delay >> 12) & 0xF);
  const s32 min = (delay_size & (1u << 11)) ? com3 : 0;
  s32 seq = read_delay + 2;
  if (delay_size & (1u << 8)) seq += com0;
  if (delay_size & (1u << 10)) seq += com2;
  const s32 first = std::max(read_delay + 4, min + 6);
  seq = std::max(seq, min + 2);
  return static_cast<u32>(first + static_cast<s32>(units - 1) * seq);
}

// The units of the region's data bus (8 or 16 bits wide, Delay/Size bit 12) that hold bytes
// first..first+count-1 of a word: what a read of just those bytes takes.
constexpr u32 memory_bus_units(u32 delay_size, u32 first, u32 count) {
  if (!(delay_size & (1u << 12))) return count;
  return ((first + count - 1) >> 1) - (first >> 1) + 1;
}

// Total cycles of an aligned read of `width` bytes (1, 2 or 4), the load's own issue cycle
// included.
constexpr u32 memory_read_cycles(u32 delay_size, u32 com_delay, u32 width) {
  return memory_read_unit_cycles(delay_size, com_delay, memory_bus_units(delay_size, 0, width));
}

// Cycles a DMA channel spends per 32-bit word moved over a region's bus: psx-spx's rule as it
// stands (COM0-1 and COM2 in FIRST too, FIRST gaining 1 while below 6), less one cycle. It gives
// the CD-ROM DMA rates psx-spx lists ("DMA Transfer Rates": 24 clocks a word with the BIOS's
// 0x00020843, 40 with the games' 0x00020943), which the CPU read rule above does not (25, 40).
constexpr u32 dma_word_cycles(u32 delay_size, u32 com_delay) {
  const s32 read_delay = static_cast<s32>((delay_size >> 4) & 0xF);
  const s32 com0 = static_cast<s32>(com_delay & 0xF);
  const s32 com2 = static_cast<s32>((com_delay >> 8) & 0xF);
  const s32 com3 = static_cast<s32>((com_delay >> 12) & 0xF);
  s32 first = 0, seq = 0;
  if (delay_size & (1u << 8)) first += com0 - 1, seq += com0 - 1;
  if (delay_size & (1u << 10)) first += com2, seq += com2;
  const s32 min = (delay_size & (1u << 11)) ? com3 : 0;
  if (first < 6) first += 1;
  first = std::max(first + read_delay + 2, min + 6);
  seq = std::max(seq + read_delay + 2, min + 2);
  const s32 units = (delay_size & (1u << 12)) ? 2 : 4;
  return static_cast<u32>(first + (units - 1) * seq - 1);
}

}  // namespace psx
