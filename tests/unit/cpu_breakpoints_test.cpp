// COP0 hardware breakpoints on a bare CPU (psx-spx "COP0 - Debug Registers"): the vector follows
// SR.BEV (80000040h, or BFC00140h with BEV set, per psx-spx's exception vector table), and DCIC
// bits 23, 30 and 31 arm execution breaks in kernel and user mode alike, bit 29 playing no part
// (pcsx-redux's hardware-run cop0 tests break from kernel mode with bit 29 clear).
// tests/roms/cpu_breakpoints covers the break kinds from inside the console.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "core/cpu/cpu_impl.h"

namespace psx {
namespace {

// 64 KiB of memory seen at every segment's physical address 0.
class FlatBus {
 public:
  FlatBus() : mem_(0x10000, 0) {}
  void put(u32 addr, u32 word) { std::memcpy(&mem_[addr & 0xFFFC], &word, 4); }
  bool fetch(u32 a, u32& v) { return read(a, v, 4); }
  bool read32(u32 a, u32& v) { return read(a, v, 4); }
  bool read16(u32 a, u32& v) { return read(a, v, 2); }
  bool read8(u32 a, u32& v) { return read(a, v, 1); }
  bool write32(u32 a, u32 v) { return write(a, v, 4); }
  bool write16(u32 a, u32 v) { return write(a, v, 2); }
  bool write8(u32 a, u32 v) { return write(a, v, 1); }
  void isolated_store(u32, u32) {}

 private:
  bool read(u32 a, u32& v, u32 n) {
    v = 0;
    std::memcpy(&v, &mem_[a & 0xFFFF], n);
    return true;
  }
  bool write(u32 a, u32 v, u32 n) {
    std::memcpy(&mem_[a & 0xFFFF], &v, n);
    return true;
  }
  std::vector<u8> mem_;
};

constexpr u32 kNop = 0;
constexpr u32 kDE = 1u << 23, kPCE = 1u << 24, kBit29 = 1u << 29, kME = 1u << 30, kTR = 1u << 31;

struct Rig {
  Scheduler sched;
  InterruptController irq;
  Gte gte;
  FlatBus bus;
  CpuT<FlatBus> cpu{bus, sched, irq, gte};
  Rig() {
    for (u32 a = 0x1000; a < 0x1040; a += 4) bus.put(a, kNop);
    cpu.reset();
    cpu.set_pc(0x1000);
  }
  void arm(u32 bpc, u32 dcic) {
    cpu.cop0().bpc = bpc;
    cpu.cop0().bpcm = 0xFFFFFFFF;
    cpu.cop0().dcic = dcic;
  }
};

TEST(CpuBreakpoints, BevSelectsTheRomDebugVector) {
  Rig r;  // reset leaves SR.BEV set
  r.arm(0x1008, kDE | kPCE | kME | kTR);
  r.cpu.step();
  r.cpu.step();
  r.cpu.step();
  EXPECT_EQ(r.cpu.pc(), 0xBFC00140u);
  EXPECT_EQ((r.cpu.cop0().cause >> 2) & 0x1F, 0x09u);
  EXPECT_EQ(r.cpu.cop0().epc, 0x1008u);
  EXPECT_EQ(r.cpu.cop0().dcic & 0x3F, 0x03u);
}

TEST(CpuBreakpoints, RamDebugVectorWithoutBev) {
  Rig r;
  r.cpu.cop0().sr = 0;
  r.arm(0x1000, kDE | kPCE | kME | kTR);
  r.cpu.step();
  EXPECT_EQ(r.cpu.pc(), 0x80000040u);
}

TEST(CpuBreakpoints, BreaksArmInEveryModeWithBit30) {
  Rig r;
  r.cpu.cop0().sr = 0x2;  // KUc: user mode
  r.arm(0x1000, kDE | kPCE | kBit29 | kTR);
  r.cpu.step();
  EXPECT_EQ(r.cpu.pc(), 0x1004u) << "bit 29 does not stand in for bit 30";
  EXPECT_EQ(r.cpu.cop0().dcic & 0x3F, 0u) << "an unarmed break sets no status bit";
  r.arm(0x1004, kDE | kPCE | kME | kTR);
  r.cpu.step();
  EXPECT_EQ(r.cpu.pc(), 0x80000040u);
  EXPECT_EQ(r.cpu.cop0().sr & 0x3F, 0x08u) << "the KU/IE stack is pushed: user mode becomes previous";
}

}  // namespace
}  // namespace psx
