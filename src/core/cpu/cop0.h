// COP0, the system control coprocessor of the R3000A (psx-spx "COP0 - Register Summary"):
// status (SR), exception cause, EPC, BadVaddr and the debug/breakpoint registers.
#pragma once
#include "core/state.h"
#include "core/types.h"

namespace psx {

// Cause.ExcCode values the PlayStation raises (psx-spx "COP0 - Exception Handling").
enum class Exception : u32 {
  Interrupt = 0x00,
  AddressLoad = 0x04,   // AdEL: misaligned or kernel address from user mode, load or fetch
  AddressStore = 0x05,  // AdES
  BusFetch = 0x06,      // IBE
  BusData = 0x07,       // DBE
  Syscall = 0x08,
  Break = 0x09,
  Reserved = 0x0A,     // RI
  CopUnusable = 0x0B,  // CpU
  Overflow = 0x0C,
};

struct Cop0 {
  // SR bits
  static constexpr u32 kIEc = 1u << 0;
  static constexpr u32 kKUc = 1u << 1;
  static constexpr u32 kIsC = 1u << 16;  // isolate cache: stores go to the cache, not memory
  static constexpr u32 kBEV = 1u << 22;  // boot exception vectors in ROM
  static constexpr u32 kCU0 = 1u << 28;
  static constexpr u32 kCU2 = 1u << 30;
  // Cause bits
  static constexpr u32 kBD = 1u << 31;
  static constexpr u32 kIP2 = 1u << 10;  // hardware interrupt from I_STAT & I_MASK
  static constexpr u32 kCauseWritable = 0x300;  // only the software interrupt bits IP0/IP1
  static constexpr u32 kPRId = 0x00000002;      // CW33300 (LSI R3000A) revision
  // DCIC (psx-spx "COP0 - Debug Registers"): status bits 0-5, which a break sets...
  static constexpr u32 kDcicDB = 1u << 0;  // any break
  static constexpr u32 kDcicPC = 1u << 1;  // BPC program counter break
  static constexpr u32 kDcicDA = 1u << 2;  // BDA data address break
  static constexpr u32 kDcicR = 1u << 3;   // ... on a read
  static constexpr u32 kDcicW = 1u << 4;   // ... on a write
  // ...and enables. psx-spx names bit 23 "super-master enable 1" and bit 31 "super-master enable
  // 2" for bits 24-29, bit 30 the master enable for bits 24-27 (execution and data breaks) and bit
  // 29 the one for bit 28 (the any-jump break, not modelled). Bits 29/30 are no kernel/user mode
  // selectors (the LR33300's KD/UD reading): pcsx-redux's hardware-run cop0 tests arm a data break
  // from kernel mode with DCIC CA800000h (bit 29 clear) and it fires.
  static constexpr u32 kDcicDE = 1u << 23;
  static constexpr u32 kDcicPCE = 1u << 24;
  static constexpr u32 kDcicDAE = 1u << 25;
  static constexpr u32 kDcicDR = 1u << 26;
  static constexpr u32 kDcicDW = 1u << 27;
  static constexpr u32 kDcicME = 1u << 30;
  static constexpr u32 kDcicTR = 1u << 31;
  static constexpr u32 kDcicWritable = 0xFF80F03F;  // bits 6-11 and 16-22 always read zero

  u32 bpc = 0, bda = 0, jumpdest = 0, dcic = 0, badvaddr = 0, bdam = 0, bpcm = 0;
  u32 sr = 0, cause = 0, epc = 0;

  // Whether every DCIC enable in `enables` is set with the three master enables (any CPU mode).
  bool break_armed(u32 enables) const {
    const u32 need = kDcicDE | kDcicME | kDcicTR | enables;
    return (dcic & need) == need;
  }

  void do_state(StateIO& s) {
    s.section("COP0", 1);
    s.pod(bpc), s.pod(bda), s.pod(jumpdest), s.pod(dcic), s.pod(badvaddr);
    s.pod(bdam), s.pod(bpcm), s.pod(sr), s.pod(cause), s.pod(epc);
    s.end_section("COP0");
  }
};

}  // namespace psx
