// R3000A instruction fields (psx-spx "CPU Opcode Encoding") and which registers an instruction
// reads, shared by the interpreter (cpu_impl.h) and the recompiler (recompiler/).
#pragma once
#include "core/types.h"

namespace psx {

namespace cpu_detail {
inline u32 op(u32 i) { return i >> 26; }
inline u32 rs(u32 i) { return (i >> 21) & 31; }
inline u32 rt(u32 i) { return (i >> 16) & 31; }
inline u32 rd(u32 i) { return (i >> 11) & 31; }
inline u32 shamt(u32 i) { return (i >> 6) & 31; }
inline u32 funct(u32 i) { return i & 63; }
inline u32 imm(u32 i) { return i & 0xFFFF; }
inline u32 simm(u32 i) { return static_cast<u32>(static_cast<s32>(static_cast<s16>(i & 0xFFFF))); }
// JR or JALR: the only jumps whose target is not word-aligned by construction.
inline bool jumps_by_register(u32 i) { return op(i) == 0 && (funct(i) == 0x08 || funct(i) == 0x09); }

// Whether instruction i is a load that goes to memory (LB..LWR, LWC2): one that meets a port load's
// bus tail (CpuT::meets_tail()).
inline bool loads_memory(u32 i) { return (op(i) >= 0x20 && op(i) <= 0x26) || op(i) == 0x32; }

// Where a port load's bus tail ends (CpuT::io_tail()), counted in cycles past kIoTail: 1 when the
// first instruction after the load meets it, 2 the second, 3 neither. kTailUnknown: neither
// instruction known yet; kTailPastFirst: the first known not to meet it, the second not known.
inline constexpr u32 kTailUnknown = 0, kTailPastFirst = 4, kTailReaches = 5;

// Whether instruction i reads general register r (nonzero) as a source operand.
inline bool reads_reg(u32 i, u32 r) {
  const bool s = rs(i) == r, t = rt(i) == r;
  if (!s && !t) return false;  // most instructions: the register is in neither field
  switch (op(i)) {
    case 0x00:
      switch (funct(i)) {
        case 0x00: case 0x02: case 0x03: return t;            // shifts by an immediate
        case 0x08: case 0x09: case 0x11: case 0x13: return s;  // JR, JALR, MTHI, MTLO
        case 0x0C: case 0x0D: case 0x10: case 0x12: return false;  // SYSCALL, BREAK, MFHI, MFLO
        default: return s || t;
      }
    case 0x02: case 0x03: case 0x0F: return false;          // J, JAL, LUI
    case 0x04: case 0x05: return s || t;                    // BEQ, BNE
    case 0x10: case 0x12: return (rs(i) == 0x04 || rs(i) == 0x06) && t;  // MTC0, MTC2, CTC2
    case 0x22: case 0x26: return s || t;                    // LWL, LWR merge into rt
    case 0x28: case 0x29: case 0x2A: case 0x2B: case 0x2E: return s || t;  // stores
    default: return s;  // BcondZ, BLEZ, BGTZ, immediate ALU, loads, LWC2, SWC2: the base
  }
}

// The multiply/divide unit's timing (psx-spx "CPU Timings"), shared by the interpreter and the
// recompiler's native code: the early-out multiplier takes 6, 9 or 13 cycles by the magnitude of
// rs (below kMultiplyFastBelow, below kMultiplyMediumBelow, else), a divide always 36.
inline constexpr u32 kMultiplyFastBelow = 0x800, kMultiplyMediumBelow = 0x100000;
inline constexpr u32 kMultiplyFastCycles = 6, kMultiplyMediumCycles = 9, kMultiplySlowCycles = 13;
inline constexpr u32 kDivideCycles = 36;
inline constexpr u32 multiply_cycles(u32 magnitude) {
  return magnitude < kMultiplyFastBelow     ? kMultiplyFastCycles
         : magnitude < kMultiplyMediumBelow ? kMultiplyMediumCycles
                                            : kMultiplySlowCycles;
}

}  // namespace cpu_detail

}  // namespace psx
