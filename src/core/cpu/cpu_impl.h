// R3000A instruction semantics (psx-spx "CPU Specifications"), included by the translation units
// that instantiate CpuT: cpu.cpp for the console's Bus, and the CPU unit tests for a test bus.
#pragma once
#include <algorithm>
#include <type_traits>

#include "core/cpu/cpu.h"
#include "core/cpu/decode.h"
#include "core/cpu/idle_skip.h"
#include "core/cpu/recompiler/recompiler.h"

namespace psx {

template <class BusT>
void CpuT<BusT>::reset() {
  regs_ = {};
  hi_ = lo_ = 0;
  cop0_ = Cop0{};
  cop0_.sr = Cop0::kBEV;  // boot vectors in ROM, caches not isolated, kernel mode
  set_pc(kResetVector);
}

template <class BusT>
void CpuT<BusT>::set_pc(u32 pc) {
  pc_ = pc;
  next_pc_ = pc + 4;
  next_in_delay_ = false;
  // A load still in flight lands now rather than being lost.
  regs_[load_reg_] = load_val_;
  regs_[0] = 0;
  load_reg_ = new_load_reg_ = 0;
  hook_armed_ = false;
  arm_hook(pc);
}

template <class BusT>
void CpuT<BusT>::run() {
  if (recompiler_) {
    recompiler_->run(*this);
    return;
  }
  stop_ = false;
  while (!stop_ && sched_.now() < sched_.next_deadline()) {
    if constexpr (std::is_same_v<BusT, Bus>) {
      if (at_loop_head()) {
        loop_head_ = kNoLoopHead;
        idle_skip_->at_loop_head(*this);
        continue;
      }
    }
    step();
  }
}

template <class BusT>
bool CpuT<BusT>::interrupt_pending() const {
  // Cause.IP2 follows (I_STAT & I_MASK) directly; IP0/IP1 are the software interrupt bits.
  if (!(cop0_.sr & Cop0::kIEc)) return false;
  u32 ip = (cop0_.cause & 0x300) | (irq_.pending() ? Cop0::kIP2 : 0);
  return (ip & cop0_.sr & 0xFF00) != 0;
}

template <class BusT>
void CpuT<BusT>::step() {
  if (hook_armed_) {
    if (pc_ == hook_pc_ && !next_in_delay_) {
      hook_armed_ = false;
      u32 before = pc_;
      hooks_->on_reach(pc_);
      if (pc_ != before) return;  // the hook redirected the CPU (an HLE call returned)
    } else if (!next_in_delay_) {
      hook_armed_ = false;
    }
  }
  if (interrupt_pending()) {
    take_interrupt();
    return;
  }
  execute_at_pc();
}

template <class BusT>
void CpuT<BusT>::execute_at_pc() {
  current_pc_ = pc_;
  in_delay_slot_ = next_in_delay_;
  next_in_delay_ = false;
  ++instructions_;
  sched_.advance(1);

  u32 instr;
  if (pc_ & 3) {
    cop0_.badvaddr = pc_;
    exception(Exception::AddressLoad);
  } else if ((cop0_.dcic & Cop0::kDcicPCE) && exec_break()) {
    // the debug exception was taken instead of the instruction
  } else if (!fetch(instr)) {
    exception(Exception::BusFetch);
  } else {
    if (kLoadShadow && shadow_reg_) shadow_stall(instr);
    pc_ = next_pc_;
    next_pc_ += 4;
    execute(instr);
  }
  // The load issued by the previous instruction lands now; this instruction's load is pending.
  // Without one the pipeline holds zero rather than an old value, so that what the state records
  // depends only on the last instruction (idle skipping relies on it, idle_skip.h).
  regs_[load_reg_] = load_val_;
  regs_[0] = 0;
  load_reg_ = new_load_reg_;
  load_val_ = new_load_val_;
  new_load_reg_ = 0;
  new_load_val_ = 0;
}

template <class BusT>
void CpuT<BusT>::take_interrupt() {
  // A GTE command at the interrupted address is executed by the hardware anyway; the BIOS
  // handler knows this and resumes after it (psx-spx "COP0 - Interrupt Handling").
  u32 next;
  if (!next_in_delay_ && (pc_ & 3) == 0 && bus_.fetch(pc_, next) && (next >> 25) == 0x25 &&
      (cop0_.sr & Cop0::kCU2)) {
    wait_gte();
    gte_ready_at_ = sched_.now() + gte_.execute(next & 0x1FFFFFF);
  }
  current_pc_ = pc_;
  in_delay_slot_ = next_in_delay_;
  next_in_delay_ = false;
  exception(Exception::Interrupt);
}

template <class BusT>
void CpuT<BusT>::exception(Exception code, u32 coprocessor, u32 vector_offset) {
  cop0_.cause = (cop0_.cause & ~(Cop0::kBD | 0x3000007Cu)) | (static_cast<u32>(code) << 2) | (coprocessor << 28);
  if (in_delay_slot_) {
    cop0_.cause |= Cop0::kBD;
    cop0_.epc = current_pc_ - 4;
    cop0_.jumpdest = pc_;
  } else {
    cop0_.epc = current_pc_;
  }
  // Push the KU/IE stack: current -> previous -> old, then kernel mode with interrupts off.
  cop0_.sr = (cop0_.sr & ~0x3Fu) | ((cop0_.sr << 2) & 0x3F);
  u32 vector = ((cop0_.sr & Cop0::kBEV) ? 0xBFC00100 : 0x80000000) + vector_offset;
  pc_ = vector;
  next_pc_ = vector + 4;
  next_in_delay_ = false;
  in_delay_slot_ = false;
  new_load_reg_ = 0;
  arm_hook(vector);
}

// COP0 hardware breakpoints (psx-spx "COP0 - Debug Registers"): a break sets DCIC's status bits
// and raises a Bp exception (ExcCode 09h, EPC/BD as for any exception) at the debug vector
// 0x80000040 (0xBFC00140 with SR.BEV). An execution break is taken instead of the instruction, so
// the handler returns to EPC to run it. A data break is taken after the access: pcsx-redux's
// hardware-run tests (src/mips/tests/cop0/cop0.c) see the matching SW and SB carried out and EPC =
// the store, so a handler resumes at EPC+4.
template <class BusT>
bool CpuT<BusT>::exec_break() {
  if (((pc_ ^ cop0_.bpc) & cop0_.bpcm) != 0 || !cop0_.break_armed(Cop0::kDcicPCE)) return false;
  cop0_.dcic |= Cop0::kDcicDB | Cop0::kDcicPC;
  exception(Exception::Break, 0, kDebugVector);
  return true;
}

// Whether an access of `count` bytes from `first` breaks: when any byte it touches meets psx-spx's
// condition ((addr XOR BDA) AND BDAM) = 0, so a partial or unaligned access (SB into a watched
// word, SWL/SWR covering the watched byte) is caught as well as an exact one. A break sets the
// status bits; the caller makes the access, then take_data_break().
template <class BusT>
bool CpuT<BusT>::data_break(u32 first, u32 count, bool write) {
  if (!cop0_.break_armed(Cop0::kDcicDAE | (write ? Cop0::kDcicDW : Cop0::kDcicDR))) return false;
  for (u32 a = first; a != first + count; ++a) {
    if (((a ^ cop0_.bda) & cop0_.bdam) == 0) {
      cop0_.dcic |= Cop0::kDcicDB | Cop0::kDcicDA | (write ? Cop0::kDcicW : Cop0::kDcicR);
      return true;
    }
  }
  return false;
}

// The Bp exception after a data access that broke. A load's value still arrives: the access was
// made and the instruction is complete, as the store's is (no hardware test reads the register;
// see docs/fidelity.md).
template <class BusT>
void CpuT<BusT>::take_data_break() {
  const u32 reg = new_load_reg_, value = new_load_val_;
  exception(Exception::Break, 0, kDebugVector);
  new_load_reg_ = reg;
  new_load_val_ = value;
}

template <class BusT>
void CpuT<BusT>::wait_muldiv() {
  if (sched_.now() < muldiv_ready_at_) sched_.advance(muldiv_ready_at_ - sched_.now());
}

template <class BusT>
void CpuT<BusT>::wait_gte() {
  if (sched_.now() < gte_ready_at_) sched_.advance(gte_ready_at_ - sched_.now());
}

// A load's bus read and its time (the load-shadow model at CpuT::kLoadIssue).
template <class BusT>
bool CpuT<BusT>::timed_read(u32 addr, u32 width, u32 rt, u32& v, u32 first, u32 count) {
  if constexpr (kLoadShadow) {
    if (BusT::physical(addr) < 0x00800000 && bus_.cached_code(current_pc_)) {
      const Cycles issue_end = sched_.now() - 1 + kLoadIssue;
      const Cycles bus_free = load_done_at_ + (load_reg_ == rt && rt != 0 ? 1 : 0);
      const Cycles start = std::max(issue_end + 1, bus_free);
      sched_.advance(start - 1 - sched_.now());
      load_done_at_ = start + kLoadBus;
      shadow_reg_ = rt;
      return bus_.read_ram_untimed(addr, v, width);
    }
    wait_load();
    if (count != 4) {
      if (!bus_.read_merged(addr, v, first, count)) return false;
      io_tail(addr, rt);
      return true;
    }
  }
  const bool ok = width == 4 ? bus_.read32(addr, v) : width == 2 ? bus_.read16(addr, v) : bus_.read8(addr, v);
  if constexpr (kLoadShadow) {
    if (ok) io_tail(addr, rt);
  }
  return ok;
}

// io_tail() is called with the read made (the time at the next instruction's start) and the pc
// at the next instruction: the tail's end as the comment at kIoTail says, from the next two
// instructions (the second follows the first in memory, also as a branch's delay slot), looked
// at here where the caller does not know them. Memory accesses wait for it (wait_load(), a
// fetch's busy_until), and so does a reader of rt after the delay slot (shadow_stall()).
template <class BusT>
u32 CpuT<BusT>::tail_reach(u32 known, u32 rt) const {
  if (known == cpu_detail::kTailUnknown && meets_tail(pc_)) return 1;
  return meets_tail(pc_ + 4, rt) ? 2 : 3;
}

template <class BusT>
bool CpuT<BusT>::meets_tail(u32 vaddr, u32 reader) const {
  if constexpr (kLoadShadow) {
    using namespace cpu_detail;
    u32 w;
    if (bus_.fetch_misses(vaddr)) return true;
    return bus_.peek_code(vaddr, w) && (loads_memory(w) || (reader != 0 && reads_reg(w, reader)));
  }
  return false;
}

// An instruction (its cycle already counted) that reads the register a load in flight brings
// ends no earlier than the load's access. In the load's delay slot (the previous instruction was
// the load: load_reg_ is its target) it reads the old value and goes on.
template <class BusT>
void CpuT<BusT>::shadow_stall(u32 instr) {
  if (sched_.now() >= load_done_at_) {
    shadow_reg_ = 0;
  } else if (load_reg_ != shadow_reg_ && cpu_detail::reads_reg(instr, shadow_reg_)) {
    wait_load();
    shadow_reg_ = 0;
  }
}

template <class BusT>
bool CpuT<BusT>::check_address(u32 addr, u32 align_mask, Exception code) {
  // Misaligned, or a kernel-segment address while in user mode.
  if ((addr & align_mask) || ((cop0_.sr & Cop0::kKUc) && (addr & 0x80000000))) {
    cop0_.badvaddr = addr;
    exception(code);
    return false;
  }
  return true;
}

template <class BusT>
void CpuT<BusT>::load(u32 instr, u32 width, bool sign) {
  using namespace cpu_detail;
  u32 addr = regs_[rs(instr)] + simm(instr);
  if (!check_address(addr, width - 1, Exception::AddressLoad)) return;
  u32 v;
  if (!timed_read(addr, width, rt(instr), v)) {
    exception(Exception::BusData);
    return;
  }
  if (sign) v = width == 2 ? u32(s32(s16(v))) : u32(s32(s8(v)));
  delayed_load(rt(instr), v);
  if ((cop0_.dcic & Cop0::kDcicDAE) && data_break(addr, width, false)) take_data_break();
}

template <class BusT>
void CpuT<BusT>::load_unaligned(u32 instr, bool left) {
  using namespace cpu_detail;
  u32 addr = regs_[rs(instr)] + simm(instr);
  if ((cop0_.sr & Cop0::kKUc) && (addr & 0x80000000)) {
    cop0_.badvaddr = addr;
    exception(Exception::AddressLoad);
    return;
  }
  const u32 off = addr & 3;
  u32 word;
  // LWL merges the word's bytes 0..off, LWR its bytes off..3.
  if (!timed_read(addr & ~3u, 4, rt(instr), word, left ? 0 : off, left ? off + 1 : 4 - off)) {
    exception(Exception::BusData);
    return;
  }
  // LWL/LWR merge with the register's in-flight load value, not the stale register.
  u32 t = rt(instr);
  u32 cur = load_reg_ == t ? load_val_ : regs_[t];
  u32 sh = off * 8;
  u32 v = left ? (cur & (0x00FFFFFFu >> sh)) | (word << (24 - sh))
               : (cur & ~(0xFFFFFFFFu >> sh)) | (word >> sh);
  delayed_load(t, v);
  if ((cop0_.dcic & Cop0::kDcicDAE) && data_break(left ? addr - off : addr, left ? off + 1 : 4 - off, false))
    take_data_break();
}

template <class BusT>
void CpuT<BusT>::store(u32 instr, u32 width) {
  using namespace cpu_detail;
  u32 addr = regs_[rs(instr)] + simm(instr);
  if (!check_address(addr, width - 1, Exception::AddressStore)) return;
  u32 v = regs_[rt(instr)];
  bool ok = true;
  if (cop0_.sr & Cop0::kIsC) {  // cache isolated: the store only touches the cache
    bus_.isolated_store(addr, v);
  } else {
    // A store waits in the write queue while the pipeline stalls for an i-cache refill of the next
    // instruction, so an I/O register sees the store only after the refill (pcsx-redux
    // src/mips/tests/timers, hardware checked: a counter read right after the MODE write that
    // resets it reads below 10, the read being the first instruction of a line or not).
    if constexpr (kLoadShadow) {
      if (BusT::io_address(addr)) bus_.fill_line_ahead(pc_, load_done_at_);
    }
    // The whole register goes to the bus: memory takes the low bytes, an I/O register all of it.
    ok = width == 4 ? bus_.write32(addr, v) : width == 2 ? bus_.write16(addr, v) : bus_.write8(addr, v);
  }
  if (!ok) exception(Exception::BusData);
  else if ((cop0_.dcic & Cop0::kDcicDAE) && data_break(addr, width, true)) take_data_break();
}

template <class BusT>
void CpuT<BusT>::store_unaligned(u32 instr, bool left) {
  using namespace cpu_detail;
  u32 addr = regs_[rs(instr)] + simm(instr);
  if ((cop0_.sr & Cop0::kKUc) && (addr & 0x80000000)) {
    cop0_.badvaddr = addr;
    exception(Exception::AddressStore);
    return;
  }
  // SWL stores the register's top (offset+1) bytes into the word's bytes 0..offset; SWR stores
  // its low (4-offset) bytes into bytes offset..3. The bus sees a write of just those bytes.
  u32 v = regs_[rt(instr)];
  u32 off = addr & 3, base = addr & ~3u;
  u32 first = left ? 0 : off, last = left ? off : 3;
  bool ok = true;
  if (!(cop0_.sr & Cop0::kIsC)) ok = write_bytes(base, first, last, left ? v >> (24 - 8 * off) : v << (8 * off));
  if (!ok) exception(Exception::BusData);
  else if ((cop0_.dcic & Cop0::kDcicDAE) && data_break(base + first, last - first + 1, true)) take_data_break();
}

// SWL/SWR's bus writes: bytes first..last of the word at base, from `data` (byte b in bits 8b..).
template <class BusT>
bool CpuT<BusT>::write_bytes(u32 base, u32 first, u32 last, u32 data) {
  if (first == 0 && last == 3) return bus_.write32(base, data);
  for (u32 b = first; b <= last; ++b)
    if (!bus_.write8(base + b, (data >> (8 * b)) & 0xFF)) return false;
  return true;
}

}  // namespace psx

#include "core/cpu/cpu_execute.h"
