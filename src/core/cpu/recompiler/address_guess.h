// A guess, while a block is compiled, at where its loads and stores will go: the registers'
// values when the block is compiled, updated by the LUI/ORI/ADDIU constants the block builds
// before each access (any other write makes a register unknown). A load or store whose guessed
// address lies outside RAM and the scratchpad is compiled as a call step: as native code it
// would check the address, take that call anyway, and check the segment's guard again after it.
// Except a plain load from or store to an I/O port (a poll of JOY_STAT, I_STAT or GPUSTAT, a write
// to GP0 or a DMA register, typically), which the native code makes at that address with one call
// for the port's read or write (Impl::io_access()).
// Only speed depends on the guess: native or a call, the instruction does exactly what the
// interpreter does.
#pragma once
#include <array>

#include "core/bus.h"
#include "core/cpu/decode.h"
#include "core/cpu/recompiler/block_emitter.h"

namespace psx {

class AddressGuess {
 public:
  explicit AddressGuess(const std::array<u32, 32>& regs) : val_(regs) {}

  // Whether instruction i is a load or store whose guessed address the native code does not
  // access itself.
  bool elsewhere(u32 i) const {
    using namespace cpu_detail;
    const u32 s = rs(i);
    const bool memory = (op(i) >= 0x20 && op(i) <= 0x2E) || op(i) == 0x32 || op(i) == 0x3A;  // LWC2, SWC2
    if (!memory || !((known_ >> s) & 1)) return false;
    return !native_memory(val_[s] + simm(i));
  }
  // The I/O port instruction i (compiled as `native`) reaches where it is an LB, LH, LW, LBU, LHU,
  // SB, SH or SW whose guessed address is aligned and in the I/O region (through KUSEG, KSEG0 or
  // KSEG1); else 0.
  u32 io_port(u32 i, NativeOp native) const {
    using namespace cpu_detail;
    const bool plain =
        (native >= NativeOp::Lb && native <= NativeOp::Lhu) || (native >= NativeOp::Sb && native <= NativeOp::Sw);
    if (!plain || !((known_ >> rs(i)) & 1)) return 0;
    const u32 a = val_[rs(i)] + simm(i);
    return (a & (access_width(native) - 1)) == 0 && Bus::io_address(a) ? a : 0;
  }
  // Follows what instruction i writes.
  void after(u32 i) {
    using namespace cpu_detail;
    const u32 s = rs(i), t = rt(i);
    const bool known = (known_ >> s) & 1;
    if (op(i) == 0x0F) return set(t, imm(i) << 16);                  // LUI
    if (op(i) == 0x0D && known) return set(t, val_[s] | imm(i));     // ORI
    if (op(i) == 0x09 && known) return set(t, val_[s] + simm(i));    // ADDIU
    forget(t);  // whichever field another instruction writes, if any
    forget(rd(i));
    if (op(i) == 0x01 || op(i) == 0x03) forget(31);  // BcondZ and JAL links
  }

  // RAM (below 8 MiB in KUSEG, KSEG0 or KSEG1) or the scratchpad (KUSEG or KSEG0), as the
  // native loads and stores tell them apart (block_emitter_memory.cpp).
  static bool native_memory(u32 a) {
    const u32 segment = a >> 29;
    if ((a & 0x1F800000) == 0) return (0x31 >> segment) & 1;
    return (segment == 0 || segment == 4) && (a & 0x1FFFFC00) == 0x1F800000;
  }

 private:
  void set(u32 r, u32 v) {
    if (r == 0) return;
    val_[r] = v;
    known_ |= 1u << r;
  }
  void forget(u32 r) {
    if (r != 0) known_ &= ~(1u << r);
  }

  std::array<u32, 32> val_;
  u32 known_ = 0xFFFFFFFF;  // bit r: val_[r] is the guess for register r
};

}  // namespace psx
