// The recompiler's steps (recompiler.h): the generic one, which runs CpuT::execute_at_pc(), and
// the fast one for code on the console's bus, which skips fetch and decode when the i-cache holds
// the word the block was compiled from, running that instruction's semantics chosen at compile
// time. Each does exactly what one pass of CpuT::run()'s loop does.
#pragma once
#include <stdexcept>

#include "core/cpu/decode.h"

namespace psx {

// The instructions the recompiler knows by name (block_emitter.h NativeOp): the register-only
// ALU operations, which touch neither memory nor coprocessors and raise no exception, HI/LO
// moves, multiplies and divides, the GTE's register moves, loads, stores and commands, the loads and stores of
// a byte, halfword or word (LWL/LWR/SWL/SWR included), and the branches and jumps; None for
// everything else.
template <class BusT>
NativeOp RecompilerT<BusT>::decode_op(u32 i) {
  static constexpr NativeOp kPrimary[48] = {
      NativeOp::None, NativeOp::None, NativeOp::J, NativeOp::Jal, NativeOp::Beq, NativeOp::Bne,
      NativeOp::Blez, NativeOp::Bgtz, NativeOp::None, NativeOp::Addiu, NativeOp::Slti, NativeOp::Sltiu,
      NativeOp::Andi, NativeOp::Ori, NativeOp::Xori, NativeOp::Lui,
      NativeOp::None, NativeOp::None, NativeOp::None, NativeOp::None, NativeOp::None, NativeOp::None,
      NativeOp::None, NativeOp::None, NativeOp::None, NativeOp::None, NativeOp::None, NativeOp::None,
      NativeOp::None, NativeOp::None, NativeOp::None, NativeOp::None,
      NativeOp::Lb, NativeOp::Lh, NativeOp::Lwl, NativeOp::Lw, NativeOp::Lbu, NativeOp::Lhu,
      NativeOp::Lwr, NativeOp::None, NativeOp::Sb, NativeOp::Sh, NativeOp::Swl, NativeOp::Sw,
      NativeOp::None, NativeOp::None, NativeOp::Swr, NativeOp::None};
  const u32 op = i >> 26;
  if (op == 0x12) {  // COP2: a command (imm25), or MFC2/CFC2/MTC2/CTC2 as execute_cop2() decodes them
    if (i & (1u << 25)) return NativeOp::Gte;
    switch (cpu_detail::rs(i)) {
      case 0x00: return NativeOp::Mfc2;
      case 0x02: return NativeOp::Cfc2;
      case 0x04: return NativeOp::Mtc2;
      case 0x06: return NativeOp::Ctc2;
      default: return NativeOp::None;
    }
  }
  if (op == 0x32) return NativeOp::Lwc2;
  if (op == 0x3A) return NativeOp::Swc2;
  if (op == 0x01) {  // BcondZ as CpuT::execute_bcondz() decodes it: bit 16 (>= 0), bits 20-17 (link)
    const u32 r = cpu_detail::rt(i);
    const bool link = (r & 0x1E) == 0x10;
    if (r & 1) return link ? NativeOp::Bgezal : NativeOp::Bgez;
    return link ? NativeOp::Bltzal : NativeOp::Bltz;
  }
  if (op != 0) return op < 48 ? kPrimary[op] : NativeOp::None;
  switch (i & 63) {
    case 0x00: return NativeOp::Sll;
    case 0x02: return NativeOp::Srl;
    case 0x03: return NativeOp::Sra;
    case 0x04: return NativeOp::Sllv;
    case 0x06: return NativeOp::Srlv;
    case 0x07: return NativeOp::Srav;
    case 0x08: return NativeOp::Jr;
    case 0x09: return NativeOp::Jalr;
    case 0x10: return NativeOp::Mfhi;
    case 0x11: return NativeOp::Mthi;
    case 0x12: return NativeOp::Mflo;
    case 0x13: return NativeOp::Mtlo;
    case 0x18: return NativeOp::Mult;
    case 0x19: return NativeOp::Multu;
    case 0x1A: return NativeOp::Div;
    case 0x1B: return NativeOp::Divu;
    case 0x21: return NativeOp::Addu;
    case 0x23: return NativeOp::Subu;
    case 0x24: return NativeOp::And;
    case 0x25: return NativeOp::Or;
    case 0x26: return NativeOp::Xor;
    case 0x27: return NativeOp::Nor;
    case 0x2A: return NativeOp::Slt;
    case 0x2B: return NativeOp::Sltu;
    default: return NativeOp::None;
  }
}

// The semantics of CpuT::execute() for the ALU instructions and the loads and stores with a call
// step of their own (step_for()); the others through CpuT::execute() itself (cpu_execute.h).
template <class BusT>
template <NativeOp K>
void RecompilerT<BusT>::exec(Cpu& c, u32 i) {
  using namespace cpu_detail;
  const u32 s = c.regs_[rs(i)], t = c.regs_[rt(i)];
  if constexpr (K == NativeOp::Addiu) c.write_reg(rt(i), s + simm(i));
  else if constexpr (K == NativeOp::Slti) c.write_reg(rt(i), s32(s) < s32(simm(i)));
  else if constexpr (K == NativeOp::Sltiu) c.write_reg(rt(i), s < simm(i));
  else if constexpr (K == NativeOp::Andi) c.write_reg(rt(i), s & imm(i));
  else if constexpr (K == NativeOp::Ori) c.write_reg(rt(i), s | imm(i));
  else if constexpr (K == NativeOp::Xori) c.write_reg(rt(i), s ^ imm(i));
  else if constexpr (K == NativeOp::Lui) c.write_reg(rt(i), imm(i) << 16);
  else if constexpr (K == NativeOp::Sll) c.write_reg(rd(i), t << shamt(i));
  else if constexpr (K == NativeOp::Srl) c.write_reg(rd(i), t >> shamt(i));
  else if constexpr (K == NativeOp::Sra) c.write_reg(rd(i), u32(s32(t) >> shamt(i)));
  else if constexpr (K == NativeOp::Addu) c.write_reg(rd(i), s + t);
  else if constexpr (K == NativeOp::Subu) c.write_reg(rd(i), s - t);
  else if constexpr (K == NativeOp::And) c.write_reg(rd(i), s & t);
  else if constexpr (K == NativeOp::Or) c.write_reg(rd(i), s | t);
  else if constexpr (K == NativeOp::Xor) c.write_reg(rd(i), s ^ t);
  else if constexpr (K == NativeOp::Nor) c.write_reg(rd(i), ~(s | t));
  else if constexpr (K == NativeOp::Slt) c.write_reg(rd(i), s32(s) < s32(t));
  else if constexpr (K == NativeOp::Sltu) c.write_reg(rd(i), s < t);
  else if constexpr (K == NativeOp::Sw || K == NativeOp::Sh || K == NativeOp::Sb) store_call<K>(c, i);
  else if constexpr (K == NativeOp::Lw || K == NativeOp::Lh || K == NativeOp::Lhu || K == NativeOp::Lb ||
                     K == NativeOp::Lbu)
    load_call<K>(c, i);
  else c.execute(i);
}

// A store's call. The native code makes RAM and scratchpad stores itself, so a store that calls
// is mostly one to an I/O port (GP0, the SPU's registers). CpuT::store() checks the alignment,
// user mode, DCIC's data break and the isolated cache, then goes through Bus::write(): where
// none of those checks can apply, an I/O store goes straight to its port. The rest, and stores
// to any other region, run as CpuT::execute().
template <class BusT>
template <NativeOp K>
void RecompilerT<BusT>::store_call(Cpu& c, u32 i) {
  using namespace cpu_detail;
  const u32 addr = c.regs_[rs(i)] + simm(i);
  const bool plain = (addr & (access_width(K) - 1)) == 0 && !(c.cop0_.sr & (Cop0::kKUc | Cop0::kIsC)) &&
                     !(c.cop0_.dcic & Cop0::kDcicDAE);
  if (!plain || !port_write<K>(c, addr, c.regs_[rt(i)])) c.execute(i);
}

// A load's call, the counterpart of store_call(): mostly a poll of an I/O port (JOY_STAT, I_STAT,
// GPUSTAT). Where CpuT::load()'s checks cannot apply (aligned, kernel mode, no DCIC data break),
// a load from the I/O region does what CpuT::load() then does: timed_read() waits for a load in
// flight (an access outside RAM does not overlap one) and reads the port, and the value, sign-
// extended for LB/LH, enters the load delay slot. The rest run as CpuT::execute().
template <class BusT>
template <NativeOp K>
void RecompilerT<BusT>::load_call(Cpu& c, u32 i) {
  using namespace cpu_detail;
  const u32 addr = c.regs_[rs(i)] + simm(i);
  const bool plain = (addr & (access_width(K) - 1)) == 0 && !(c.cop0_.sr & Cop0::kKUc) &&
                     !(c.cop0_.dcic & Cop0::kDcicDAE);
  if (!plain || !BusT::io_address(addr)) return c.execute(i);
  c.delayed_load(rt(i), port_read<K>(c, addr, rt(i)));
}

// What CpuT::load() does past its checks for an I/O port: timed_read() waits for a load in
// flight (an access outside RAM does not overlap one), reads the port and leaves its bus tail
// (CpuT::io_tail() for rt, with what the caller knows of where it ends); the value, sign-extended for
// LB/LH.
template <class BusT>
template <NativeOp K>
u32 RecompilerT<BusT>::port_read(Cpu& c, u32 address, u32 rt, u32 reach) {
  c.wait_load();
  u32 v;
  c.bus_.read_io(address, v, access_width(K));
  c.io_tail(address, rt, reach);
  if constexpr (K == NativeOp::Lh) v = u32(s32(s16(v)));
  if constexpr (K == NativeOp::Lb) v = u32(s32(s8(v)));
  return v;
}

// What CpuT::store() does past its checks: the refill of the next instruction's line first, then
// the whole register to the port (Bus::write(), which lets a narrow store write all of an I/O
// register); false where the address is no I/O port.
template <class BusT>
template <NativeOp K>
bool RecompilerT<BusT>::port_write(Cpu& c, u32 address, u32 value) {
  if constexpr (Cpu::kLoadShadow) {  // as CpuT::store() (pc_: the next instruction)
    if (BusT::io_address(address)) c.bus_.fill_line_ahead(c.pc_, c.load_done_at_);
  }
  return c.bus_.write_io(address, value, access_width(K));
}

// A native I/O load's access (Impl::io_access()): port_read(), the native code having made
// CpuT::load()'s checks and the instruction's bookkeeping, with where the bus tail ends as far as
// the compiled words tell (`Reach`, Impl::tail_plan()). Events may run during the read
// (Bus::catch_up()), so the answer's bit 32 says where the CPU may no longer run natively:
// stopped, a hook armed or an interrupt pending, as may_step() would find before the next
// instruction (the native code checks the deadline).
template <class BusT>
template <NativeOp K, u32 Reach>
u64 RecompilerT<BusT>::io_load(void* context, u32 address, u32 rt) {
  Cpu& c = *static_cast<Cpu*>(context);
  const u32 v = port_read<K>(c, address, rt, Reach);
  return v | u64{leaves_native(c)} << 32;
}

// Layout::io_loads' row for K: io_load() for each reach.
template <class BusT>
template <NativeOp K, u32... Reach>
void RecompilerT<BusT>::set_io_loads(BlockEmitter::Layout& l, std::integer_sequence<u32, Reach...>) {
  ((l.io_loads[u32(K) - u32(NativeOp::Lb)][Reach] = &io_load<K, Reach>), ...);
}

// A native I/O store's access (Impl::io_access()): port_write(), the native code having made
// CpuT::store()'s checks. The write may run events and DMA (a write to a channel's control). The
// answer's bit 32 as io_load()'s.
template <class BusT>
template <NativeOp K>
u64 RecompilerT<BusT>::io_store(void* context, u32 address, u32 value) {
  Cpu& c = *static_cast<Cpu*>(context);
  port_write<K>(c, address, value);
  return u64{leaves_native(c)} << 32;
}

// The checks at the top of CpuT::run()'s loop and CpuT::step(): whether the step can run the
// instruction itself (true), or must leave the block (false, having stepped the CPU through a
// hook or an interrupt where one was due).
template <class BusT>
inline bool RecompilerT<BusT>::may_step(Cpu& c, u32 pc) {
  if (c.stop_ || c.sched_.now() >= c.sched_.next_deadline()) return false;
  if (pc == c.loop_head_ && c.idle_skip_) return false;  // the dispatcher examines the loop
  if (c.hook_armed_ || c.interrupt_pending()) {
    c.step();
    return false;
  }
  return true;
}

template <class BusT>
bool RecompilerT<BusT>::step_at(void* context, u32 pc, u32) {
  Cpu& c = *static_cast<Cpu*>(context);
  if (!may_step(c, pc)) return false;
  c.execute_at_pc();
  return c.pc_ == pc + 4;
}

// CpuT::execute_at_pc() for an instruction fetched from a whole i-cache line (no time, no fill)
// that is still the word compiled: the same bookkeeping in the same order, with K's semantics.
template <class BusT>
template <NativeOp K>
bool RecompilerT<BusT>::step_fast(void* context, u32 pc, u32 word) {
  Cpu& c = *static_cast<Cpu*>(context);
  if (!may_step(c, pc)) return false;
  u32 fetched;
  if ((c.cop0_.dcic & Cop0::kDcicPCE) || !c.bus_.fetch_hit(pc, fetched) || fetched != word) {
    c.execute_at_pc();
    return c.pc_ == pc + 4;
  }
  c.current_pc_ = pc;
  c.in_delay_slot_ = c.next_in_delay_;
  c.next_in_delay_ = false;
  ++c.instructions_;
  c.sched_.advance(1);
  if (c.shadow_reg_) c.shadow_stall(word);
  c.pc_ = c.next_pc_;
  c.next_pc_ += 4;
  exec<K>(c, word);
  c.regs_[c.load_reg_] = c.load_val_;
  c.regs_[0] = 0;
  c.load_reg_ = c.new_load_reg_;
  c.load_val_ = c.new_load_val_;
  c.new_load_reg_ = 0;
  c.new_load_val_ = 0;
  return c.pc_ == pc + 4;
}

// The instructions emitted as native code (block_emitter.h): on the console's bus, all that
// decode_op() names (loads and stores keep their call step for accesses other than plain RAM
// and scratchpad ones, block_emitter_memory.cpp). (The scripted
// test buses have no i-cache model, so the guard could not prove a fetch free: every step there
// is a call.)
template <class BusT>
NativeOp RecompilerT<BusT>::native_for(u32 i) {
  if constexpr (!std::is_same_v<BusT, Bus>) {
    return NativeOp::None;
  } else {
    return decode_op(i);
  }
}

// Where native code finds the CPU's fields (BlockEmitter::Layout).
template <class BusT>
BlockEmitter::Layout RecompilerT<BusT>::layout(Cpu& c) {
  static_assert(sizeof(c.in_delay_slot_) == 1 && sizeof(c.next_in_delay_) == 1);
  static_assert(sizeof(c.instructions_) == 8 && sizeof(c.load_done_at_) == 8 && sizeof(Cycles) == 8);
  static_assert(sizeof(c.muldiv_ready_at_) == 8 && sizeof(c.gte_ready_at_) == 8);
  static_assert(sizeof(c.hi_) == 4 && sizeof(bool) == 1);
  static_assert(sizeof(c.pc_) == 4 && sizeof(c.load_reg_) == 4 && sizeof(c.shadow_reg_) == 4);
  static_assert(sizeof(c.stop_) == 1 && sizeof(c.hook_armed_) == 1 && sizeof(c.code_written_) == 1);
  static_assert(sizeof(c.idle_skip_) == 8);
  static_assert(sizeof(c.hooks_) == 8 && sizeof(c.hook_pc_) == 4 && sizeof(c.extra_hook_pc_) == 4);
  BlockEmitter::Layout l{};
  l.context = &c;
  // The registers at -128..-4 and the fields after them (the pc, the pipeline, the load shadow,
  // COP0) from 0 on.
  const auto at = [](const void* base, const void* field) {
    return int(static_cast<const char*>(field) - static_cast<const char*>(base));
  };
  l.bias = at(&c, c.regs_.data()) + 128;
  const auto cpu_at = [&](const void* field) { return at(&c, field) - l.bias; };
  l.sched = &c.sched_;
  l.regs = cpu_at(c.regs_.data());
  l.pc = cpu_at(&c.pc_);
  l.next_pc = cpu_at(&c.next_pc_);
  l.current_pc = cpu_at(&c.current_pc_);
  l.load_reg = cpu_at(&c.load_reg_);
  l.load_val = cpu_at(&c.load_val_);
  l.new_load_reg = cpu_at(&c.new_load_reg_);
  l.new_load_val = cpu_at(&c.new_load_val_);
  if (l.load_val != l.load_reg + 4 || l.new_load_val != l.new_load_reg + 4)
    throw std::logic_error("recompiler: the pending-load fields are not in pairs");
  l.shadow_reg = cpu_at(&c.shadow_reg_);
  l.loop_head = cpu_at(&c.loop_head_);
  l.sr = cpu_at(&c.cop0_.sr);
  l.cause = cpu_at(&c.cop0_.cause);
  l.dcic = cpu_at(&c.cop0_.dcic);
  l.stop = cpu_at(&c.stop_);
  l.hook_armed = cpu_at(&c.hook_armed_);
  if (l.hook_armed != l.stop + 1) throw std::logic_error("recompiler: hook_armed_ does not follow stop_");
  l.idle_skip = cpu_at(&c.idle_skip_);
  const IdleSkip::BackoffCells backoff = IdleSkip::backoff_cells();
  l.idle_last_head = backoff.last_head;
  l.idle_backoff = backoff.table;
  l.no_loop_head = Cpu::kNoLoopHead;
  l.hooks = cpu_at(&c.hooks_);
  l.hook_pc = cpu_at(&c.hook_pc_);
  l.extra_hook_pc = cpu_at(&c.extra_hook_pc_);
  l.in_delay_slot = cpu_at(&c.in_delay_slot_);
  l.next_in_delay = cpu_at(&c.next_in_delay_);
  l.instructions = cpu_at(&c.instructions_);
  l.load_done_at = cpu_at(&c.load_done_at_);
  l.muldiv_ready_at = cpu_at(&c.muldiv_ready_at_);
  l.gte_ready_at = cpu_at(&c.gte_ready_at_);
  l.gte = &c.gte_;
  l.gte_read_data = [](void* g, u32 r) { return static_cast<Gte*>(g)->read_data(r); };
  l.gte_read_control = [](void* g, u32 r) { return static_cast<Gte*>(g)->read_control(r); };
  l.gte_write_data = [](void* g, u32 r, u32 v) { static_cast<Gte*>(g)->write_data(r, v); };
  l.gte_write_control = [](void* g, u32 r, u32 v) { static_cast<Gte*>(g)->write_control(r, v); };
  l.gte_cycles = &Gte::command_cycles;
  if constexpr (std::is_same_v<BusT, Bus>) {
    constexpr auto reaches = std::make_integer_sequence<u32, cpu_detail::kTailReaches>{};
    set_io_loads<NativeOp::Lb>(l, reaches);
    set_io_loads<NativeOp::Lh>(l, reaches);
    set_io_loads<NativeOp::Lw>(l, reaches);
    set_io_loads<NativeOp::Lbu>(l, reaches);
    set_io_loads<NativeOp::Lhu>(l, reaches);
    l.io_stores[0] = &io_store<NativeOp::Sb>;
    l.io_stores[1] = &io_store<NativeOp::Sh>;
    l.io_stores[2] = &io_store<NativeOp::Sw>;
  }
  l.gte_longest = Gte::kLongestCommandCycles;
  l.hi = cpu_at(&c.hi_);
  l.lo = cpu_at(&c.lo_);
  l.load_issue = int(Cpu::kLoadIssue);
  l.load_bus = int(Cpu::kLoadBus);
  pages_.keep_flag_at(&c.code_written_);
  l.any_dirty = pages_.any_dirty_cell();
  l.recent_blocks = cache_.recent_table();
  l.recent_count = BlockCache::kRecent;
  l.now = at(&c.sched_, c.sched_.now_cell());
  l.deadline = at(&c.sched_, c.sched_.deadline_cell());
  if constexpr (std::is_same_v<BusT, Bus>) {  // other buses compile no native steps
    l.ram_read = int(BusT::kRamRead);
    l.irq_stat = c.irq_.stat_cell();
    l.irq_mask = c.irq_.mask_cell();
    l.icache_tags = c.bus_.icache().tags();
    l.cache_control = c.bus_.cache_control_cell();
    l.icache_enable = BusT::icache_enable_bit();
    l.icache_words = c.bus_.icache().words();
    l.hot_lines = c.bus_.hot_lines_cell();
    l.no_hot_line = BusT::no_hot_line();
    l.fetch_word_cycles = u32(BusT::kRamFetchUncached);
    l.icache_block_bits = BusT::icache_block_bits();
    l.ram = c.bus_.ram();
    l.dcache_mode = c.bus_.dcache_mode_cell();
    l.watches = c.bus_.watches_cell();
    // Native stores report to this recompiler's pages, which the console attaches to the bus
    // whenever it attaches the recompiler to the CPU (Console::set_cpu_mode).
    l.code_bits = pages_.bits();
    l.code_pages = &pages_;
    l.code_write = [](void* pages, u32 off) { static_cast<CodePages*>(pages)->on_ram_write(off); };
    l.written_pages = c.bus_.written_pages();
  }
  return l;
}

template <class BusT>
BlockEmitter::StepFn RecompilerT<BusT>::step_for(u32 word) {
  if constexpr (!std::is_same_v<BusT, Bus>) {
    return &step_at;  // a bus without the i-cache model: every step fetches
  } else {
    switch (decode_op(word)) {
#define PSXRL_REC_OP(name) \
  case NativeOp::name: return &step_fast<NativeOp::name>;
      PSXRL_REC_OP(Addiu) PSXRL_REC_OP(Slti) PSXRL_REC_OP(Sltiu) PSXRL_REC_OP(Andi) PSXRL_REC_OP(Ori)
      PSXRL_REC_OP(Xori) PSXRL_REC_OP(Lui) PSXRL_REC_OP(Sll) PSXRL_REC_OP(Srl) PSXRL_REC_OP(Sra)
      PSXRL_REC_OP(Addu) PSXRL_REC_OP(Subu) PSXRL_REC_OP(And) PSXRL_REC_OP(Or) PSXRL_REC_OP(Xor)
      PSXRL_REC_OP(Nor) PSXRL_REC_OP(Slt) PSXRL_REC_OP(Sltu) PSXRL_REC_OP(Sb) PSXRL_REC_OP(Sh) PSXRL_REC_OP(Sw)
      PSXRL_REC_OP(Lb) PSXRL_REC_OP(Lbu) PSXRL_REC_OP(Lh) PSXRL_REC_OP(Lhu) PSXRL_REC_OP(Lw)
#undef PSXRL_REC_OP
      default: return &step_fast<NativeOp::None>;  // CpuT::execute() without fetch and decode
    }
  }
}

}  // namespace psx
