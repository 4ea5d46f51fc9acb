// HLE kernel: the kernel's RAM tables (psx-spx "BIOS Memory Map"): the table of tables at 100h
// with the ExCB (exception chain heads), PCB, TCB (thread register save areas) and EvCB blocks,
// the A/B/C function tables with a stub per entry, the dispatch of vector calls through those
// tables, GetB0Table/GetC0Table, and the thread functions OpenTh/CloseTh/ChangeTh.
#include "core/bios/hle_bios.h"

#include "core/bus.h"

namespace psx {

namespace {
constexpr u32 kA0 = 0xA0, kB0 = 0xB0, kC0 = 0xC0;
constexpr u32 kA0r = 4, kA1 = 5, kA2 = 6, kT1 = 9, kGp = 28, kSp = 29, kFp = 30, kRa = 31;
constexpr u32 kNop = 0, kJrT0 = 0x01000008;
constexpr u32 j(u32 target) { return 0x08000000 | ((target >> 2) & 0x03FFFFFF); }
constexpr u32 li_t1(u32 v) { return 0x24090000 | v; }  // ADDIU t1, zero, v
// TCB layout (psx-spx "BIOS Thread Functions"): status, then r0-r31, EPC, HI, LO, SR, Cause.
constexpr u32 kTcbRegs = 0x08, kTcbEpc = 0x88, kTcbSr = 0x94;
constexpr u32 kTcbFree = 0x1000, kTcbUsed = 0x4000;
constexpr u32 kThreadHandle = 0xFF000000;
// The SR an exception would have saved for code running with sr: RFE restores sr from it.
constexpr u32 pushed_sr(u32 sr) { return (sr & ~0x3Fu) | ((sr & 0xF) << 2); }
// Table of tables offsets: ExCB, PCB, TCB, EvCB pointer (the size follows each).
constexpr u32 kExcb = 0x00, kPcb = 0x08, kTcb = 0x10, kEvcb = 0x20;

struct TableInfo {
  u32 vector, table, entries, first_stub;
};
// Stubs are numbered A entries first, then B, then C.
constexpr TableInfo kTableInfo[3] = {{kA0, 0x80000200, 0xC0, 0}, {kB0, 0x80000874, 0x80, 0xC0}, {kC0, 0x80000674, 0x20, 0x140}};
}  // namespace

// Allocates the control blocks from the kernel heap as the BIOS does at boot, and fills the
// function tables with the stubs.
void HleBios::install_tables() {
  for (u32 i = 0; i < 0x80; i += 4) poke32(kTables + i, 0);
  auto block = [&](u32 offset, u32 size) {
    u32 p = heap_alloc(kernel_heap_, size);
    for (u32 i = 0; i < size; i += 4) poke32(p + i, 0);
    poke32(kTables + offset, p);
    poke32(kTables + offset + 4, size);
    return p;
  };
  block(kExcb, 4 * 8);
  u32 pcb = block(kPcb, 4);
  u32 tcb = block(kTcb, kMaxThreads * kTcbSize);
  block(kEvcb, kMaxEvents * kEvcbSize);
  for (u32 t = 0; t < kMaxThreads; ++t) poke32(tcb + t * kTcbSize, t ? kTcbFree : kTcbUsed);
  poke32(pcb, tcb);

  for (u32 k = 0; k < 3; ++k) {
    const TableInfo& t = kTableInfo[k];
    u32 tail = kStubTails + 16 * k;
    const u32 code[4] = {0x3C08A000, 0x35080000 | t.vector, kJrT0, kNop};  // lui/ori t0, KSEG1 vector
    for (u32 i = 0; i < 4; ++i) poke32(tail + 4 * i, code[i]);
    for (u32 fn = 0; fn < t.entries; ++fn) {
      u32 stub = kStubs + 8 * (t.first_stub + fn);
      poke32(stub, j(tail));
      poke32(stub + 4, li_t1(fn));
      poke32(t.table + 4 * fn, stub);
    }
  }
}

// A call through vector A0h/B0h/C0h: through KSEG1 it comes from a stub and runs natively.
// Otherwise the function's table entry decides: a stub (of this or another function) runs that
// function natively, anything else is the program's own replacement and is jumped to. Returns
// false when the call should run natively with t1 as it is.
bool HleBios::via_table(u32 vector, u32 pc) {
  if (pc >= 0xA0000000 && pc < 0xC0000000) return false;
  const TableInfo& t = kTableInfo[vector == kA0 ? 0 : vector == kB0 ? 1 : 2];
  u32 fn = cpu_.reg(kT1) & 0xFF;
  if (fn >= t.entries) return false;
  u32 entry = peek32(t.table + 4 * fn);
  u32 stubs_end = kStubs + 8 * (kTableInfo[2].first_stub + kTableInfo[2].entries);
  if (entry >= kStubs && entry < stubs_end && !(entry & 7)) {
    u32 n = (entry - kStubs) / 8;
    for (const TableInfo& other : kTableInfo)
      if (n >= other.first_stub && n < other.first_stub + other.entries) {
        if (other.vector == vector) cpu_.set_reg(kT1, n - other.first_stub);
        else cpu_.set_pc(entry);  // another table's stub: it reaches its own vector natively
        return other.vector != vector;
      }
  }
  cpu_.set_pc(entry);
  return true;
}

u32 HleBios::chain_head(u32 prio) const { return peek32(peek32(kTables + kExcb) + 8 * (prio & 3)); }

void HleBios::set_chain_head(u32 prio, u32 elem) { poke32(peek32(kTables + kExcb) + 8 * (prio & 3), elem); }

u32 HleBios::current_tcb() const { return peek32(peek32(kTables + kPcb)); }

// B0h:56h GetC0Table, B0h:57h GetB0Table.
bool HleBios::table_call(u32 table, u32 fn) {
  if (table != kB0 || (fn != 0x56 && fn != 0x57)) return false;
  return_to_caller(fn == 0x56 ? kTableC : kTableB);
  return true;
}

// OpenTh(pc, sp, gp) takes a free TCB; ChangeTh saves the caller's registers in the current
// TCB (resuming at its return address with v0 = 1) and loads the other thread's, as the BIOS's
// ChangeThreadSubFunction does through SYSCALL 3.
bool HleBios::thread_call(u32 fn) {
  const u32 a0 = cpu_.reg(kA0r);
  u32 tcbs = peek32(kTables + kTcb), count = peek32(kTables + kTcb + 4) / kTcbSize;
  u32 index = a0 - kThreadHandle, tcb = tcbs + index * kTcbSize;
  switch (fn) {
    case 0x0E:  // OpenTh
      for (u32 i = 0; i < count; ++i) {
        u32 t = tcbs + i * kTcbSize;
        if (peek32(t) == kTcbUsed) continue;
        for (u32 k = 4; k < kTcbSize; k += 4) poke32(t + k, 0);
        poke32(t, kTcbUsed);
        poke32(t + kTcbEpc, a0);
        poke32(t + kTcbRegs + 4 * kSp, cpu_.reg(kA1));
        poke32(t + kTcbRegs + 4 * kFp, cpu_.reg(kA1));
        poke32(t + kTcbRegs + 4 * kGp, cpu_.reg(kA2));
        poke32(t + kTcbSr, pushed_sr(cpu_.cop0().sr));
        return_to_caller(kThreadHandle + i);
        return true;
      }
      return_to_caller(0xFFFFFFFF);
      return true;
    case 0x0F:  // CloseTh
      if (index < count) poke32(tcb, kTcbFree);
      return_to_caller(1);
      return true;
    case 0x10: {  // ChangeTh
      if (index >= count || peek32(tcb) != kTcbUsed) {
        return_to_caller(0);
        return true;
      }
      cpu_.set_reg(2, 1);
      u32 cur = current_tcb();
      for (u32 r = 0; r < 32; ++r) poke32(cur + kTcbRegs + 4 * r, cpu_.reg(r));
      poke32(cur + kTcbEpc, cpu_.reg(kRa));
      poke32(cur + kTcbEpc + 4, cpu_.hi());
      poke32(cur + kTcbEpc + 8, cpu_.lo());
      poke32(cur + kTcbSr, pushed_sr(cpu_.cop0().sr));
      poke32(peek32(kTables + kPcb), tcb);
      return_from_exception();
      return true;
    }
    default: return false;
  }
}

}  // namespace psx
