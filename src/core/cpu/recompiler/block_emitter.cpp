// Emits compiled blocks (block_emitter.h) with xbyak (System V x86-64 calling convention): a
// block's frame, the segment guard, each native instruction's bookkeeping (CpuT::execute_at_pc),
// the ALU operations. The chain to the next block: block_emitter_chain.cpp; branches:
// block_emitter_branch.cpp; loads, stores and HI/LO: block_emitter_memory.cpp; the i-cache line
// checks and fills: block_emitter_icache.cpp; the deadline's budget and the load shadow:
// block_emitter_timing.cpp.
#include "core/cpu/recompiler/block_emitter.h"

#include <algorithm>
#include <utility>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "core/cpu/cop0.h"
#include "core/cpu/decode.h"
#include "core/cpu/recompiler/emitter_impl.h"

namespace psx {

using Xbyak::Label;
using Impl = BlockEmitter::Impl;

// Where `p` lies within a signed 32-bit displacement of rbx (the context plus Layout::bias), that
// displacement: the cells of other objects a block reads often (the written-code flag, the recent
// table) are then one rbx-relative operand instead of an address loaded first. Mostly they are:
// the heap keeps a console's objects close together. Elsewhere empty.
std::optional<int> Impl::from_context(const void* p) const {
  const auto d = reinterpret_cast<intptr_t>(p) - (reinterpret_cast<intptr_t>(lay.context) + lay.bias);
  if (d < INT32_MIN || d > INT32_MAX) return std::nullopt;
  return int(d);
}

// Both leave every register but r11 as it was (a step's function in rax, its answer in al).
void Impl::flush() {
  mov(r11, reinterpret_cast<u64>(lay.sched));
  mov(qword[r11 + lay.now], now);
  mov(cpu64(lay.instructions), instructions);
}

void Impl::reload() {
  mov(r11, reinterpret_cast<u64>(lay.sched));
  mov(now, qword[r11 + lay.now]);
  mov(deadline, qword[r11 + lay.deadline]);
  mov(instructions, cpu64(lay.instructions));
}

void Impl::call_leaf(const void* fn) {
  mov(rax, reinterpret_cast<u64>(fn));
  call(rax);
}

// A step's call: its pc and word and the function in rax, through step_routine().
void Impl::call_step(const Step& s) {
  mov(esi, s.pc);
  mov(edx, s.word);
  mov(rax, reinterpret_cast<u64>(s.fn));
  call(step_routine());
  test(al, al);
  jz(*exit, T_NEAR);
}

// The call of the step function in rax with the context, as a routine of the block (emitted
// once with the cold code): a block makes a call step for each instruction's slow path and
// each load's or store's fallback, and this keeps each of them at about half the bytes. A step
// may read the time (a timer's counter, its own bookkeeping) or move it (a DMA), book an event
// before the deadline, and it counts its instruction (hooks or idle skipping may read the
// count), so the registers are written back before and read again after. Entered with the
// stack 8 bytes off the ABI's alignment (the return address).
Label& Impl::step_routine() {
  if (!step_entry) {
    step_entry = &cold_label();
    cold.push_back([this, &entry = *step_entry] {
      L(entry);
      lea(rdi, ptr[rbx - lay.bias]);
      mov(byte[rsp + 8 + kVouched], 0);  // the frame past the return address (needs_checks())
      sub(rsp, 8);
      flush();
      call(rax);
      reload();
      add(rsp, 8);
      ret();
    });
  }
  return *step_entry;
}

// The register the instruction writes through write_reg (0: none; a load's delayed write is not one).
u32 Impl::dest(NativeOp op, u32 i) {
  switch (op) {
    case NativeOp::Jal: case NativeOp::Bltzal: case NativeOp::Bgezal: return 31;
    case NativeOp::Jalr: case NativeOp::Mfhi: case NativeOp::Mflo: return cpu_detail::rd(i);
    default: break;
  }
  if (op > NativeOp::Sltu) return 0;  // MTHI, MTLO, MULT/DIV, loads, stores, other branches
  return op >= NativeOp::Sll ? cpu_detail::rd(i) : cpu_detail::rt(i);
}

// eax = the instruction's result (CpuT::execute's value for write_reg). Sources come from eax
// where it holds them (eax_reg).
void Impl::alu(NativeOp op, u32 i) {
  using namespace cpu_detail;
  const u32 s = rs(i), t = rt(i);
  // A commutative operation: rs op rt, starting from whichever eax holds.
  const auto both = [&](auto apply) {
    if (in_eax(t) && !in_eax(s)) {
      with_reg(s, [&](const Xbyak::Operand& o) { apply(o); });
    } else {
      read_eax(s);
      if (t == s) apply(eax);
      else apply(reg(t));
    }
  };
  const auto set_if = [&](u32 x, auto cmp_y, bool is_signed) {  // eax = (x < y), y as cmp_y compares
    with_reg(x, [&](const Xbyak::Operand& o) { mov(ecx, o); });
    cmp_y();
    if (is_signed) setl(al);
    else setb(al);
    movzx(eax, al);
  };
  // r0 reads 0: GCC's `li` (ADDIU/ORI from r0) and `move` (OR/ADDU with r0) become one move.
  if (s == 0 && (op == NativeOp::Addiu || op == NativeOp::Ori || op == NativeOp::Xori)) {
    mov(eax, op == NativeOp::Addiu ? simm(i) : imm(i));
    return;
  }
  if ((s == 0 || t == 0) && (op == NativeOp::Addu || op == NativeOp::Or || op == NativeOp::Xor)) {
    if (s == t) xor_(eax, eax);
    else read_eax(s == 0 ? t : s);
    return;
  }
  switch (op) {
    case NativeOp::Addiu: read_eax(s); add(eax, simm(i)); break;
    case NativeOp::Slti: set_if(s, [&] { cmp(ecx, simm(i)); }, true); break;
    case NativeOp::Sltiu: set_if(s, [&] { cmp(ecx, simm(i)); }, false); break;
    case NativeOp::Andi: read_eax(s); and_(eax, imm(i)); break;
    case NativeOp::Ori: read_eax(s); or_(eax, imm(i)); break;
    case NativeOp::Xori: read_eax(s); xor_(eax, imm(i)); break;
    case NativeOp::Lui: mov(eax, imm(i) << 16); break;
    case NativeOp::Sll: read_eax(t); shl(eax, u8(shamt(i))); break;
    case NativeOp::Srl: read_eax(t); shr(eax, u8(shamt(i))); break;
    case NativeOp::Sra: read_eax(t); sar(eax, u8(shamt(i))); break;
    // x86 masks a shift count to 5 bits, as MIPS does (s & 31).
    case NativeOp::Sllv: read_pair(t, s); shl(eax, cl); break;
    case NativeOp::Srlv: read_pair(t, s); shr(eax, cl); break;
    case NativeOp::Srav: read_pair(t, s); sar(eax, cl); break;
    case NativeOp::Addu: both([&](const Xbyak::Operand& o) { add(eax, o); }); break;
    case NativeOp::Subu: read_pair(s, t); sub(eax, ecx); break;
    case NativeOp::And: both([&](const Xbyak::Operand& o) { and_(eax, o); }); break;
    case NativeOp::Or: both([&](const Xbyak::Operand& o) { or_(eax, o); }); break;
    case NativeOp::Xor: both([&](const Xbyak::Operand& o) { xor_(eax, o); }); break;
    case NativeOp::Nor: both([&](const Xbyak::Operand& o) { or_(eax, o); }); not_(eax); break;
    case NativeOp::Slt: set_if(s, [&] { with_reg(t, [&](const Xbyak::Operand& o) { cmp(ecx, o); }); }, true); break;
    case NativeOp::Sltu: set_if(s, [&] { with_reg(t, [&](const Xbyak::Operand& o) { cmp(ecx, o); }); }, false); break;
    default: break;
  }
}

// Whether the segment may run as native code (else to its slow path): checked once for the whole
// run because its instructions change none of it. They write general registers, HI/LO, the GTE,
// the pc, the pipeline, time, and RAM or the scratchpad (never I/O, which a load or store leaves
// to the slow path), so stop_, hooks, interrupts (SR, Cause, I_STAT, I_MASK), the loop head,
// DCIC, what loads and stores need (memory_guard()) and the i-cache stay as they are (a store to
// RAM leaves the i-cache alone: it is not coherent); only the deadline, which time reaches, is
// checked again before each instruction. Every word must be a fetch without time or fill, an
// i-cache hit (Bus::fetch_slow: cached code, the line's tag matching and the word's valid bit
// set; a hit on a line held only in part is as free as on a whole one) that is still the word
// compiled, checked once per line by its tag, valid bits and stale bit (ICache::kStale):
// here for the run's first line, and for each further line where the run reaches it (native();
// nothing native changes the i-cache, so checking a line when it is reached is the same as
// checking it here), so that a run whose later lines miss runs natively up to them. Such a hit
// also means the code is cached (Bus::cached_code), as the load-shadow model asks of a native
// load.
void Impl::guard(std::span<const Step> run, Label& fail, Checks checks, std::optional<u32> budget, Label* fill,
                 Label* filled) {
  const u32 first = run[0].pc, bytes = u32(run.size()) * 4;
  const auto any = [&](bool (*pred)(NativeOp)) {
    return std::any_of(run.begin(), run.end(), [&](const Step& s) { return pred(s.native); });
  };
  const u32 needs = (any(is_memory) ? kNeedsMemory : 0) | (any(is_store_or_swc2) ? kNeedsStores : 0) |
                    (any(is_cop2) ? kNeedsCop2 : 0);
  switch (checks) {
    case Checks::all: machine_checks(needs, fail, true); break;
    case Checks::routine:
      call(machine_routine(needs));
      jnz(fail, T_NEAR);
      break;
    case Checks::entry: {  // the block's entries (kPrologueBytes, kCleanEntry) lie either side
      const size_t start = getSize();
      pc_checks(first, fail);
      pad_to(start, kPcCheckBytes, "pc checks");
      const size_t states = getSize();
      state_checks(fail);
      loop_head_check(first, bytes, fail);
      pad_to(states, kStateCheckBytes, "state and loop-head checks");
      needs_checks(needs, fail, true);
      if (loops_natively) mov(byte[rsp], 0);  // no call since this guard (chain())
      break;
    }
  }
  if (checks == Checks::all || (checks == Checks::routine && is_branch(run[0].native)))
    pc_checks(first, fail);
  if (checks != Checks::entry) loop_head_check(first, bytes, fail);
  if (run.back().pc >= 0xA0000000) {  // KSEG1 (uncached) or beyond: every fetch takes time
    jmp(fail, T_NEAR);
    return;
  }
  if (budget) budget_check(*budget, fail);
  else if (checks == Checks::entry) budget_check(0, fail);  // the deadline, for a clean chain()
  line_check(run, fail, fill, filled);
}

// A segment's first instruction (at `first`) runs natively only out of a delay slot, next_pc_
// following pc_ (native() then knows its pc_, next_pc_ and in_delay_slot_), as does a branch
// (branch() assumes it). A segment resumed after a call needs no check: the call left on the next
// instruction (call_step()), and after a branch's call its delay slot reads where it went. A
// clean chain() vouches for them too: it comes from a run that ended on an instruction other
// than a branch. Fixed-size encodings, padded to kPcCheckBytes at a block's entry.
void Impl::pc_checks(u32 first, Label& fail) {
  cmp(byte[rbx + lay.next_in_delay], 0);
  jne(fail, T_NEAR);
  cmp(cpu32(lay.next_pc), first + 4);
  jne(fail, T_NEAR);
}

// run() would hand a loop head in the `bytes` of code at `first` to IdleSkip. At a block's entry
// it lies before the clean entry (kCleanEntry), where a clean chain() that has seen no loop head
// that matters enters past it.
void Impl::loop_head_check(u32 first, u32 bytes, Label& fail) {
  Label no_loop_head;
  mov(eax, cpu32(lay.loop_head));
  sub(eax, first);
  cmp(eax, bytes);
  jae(no_loop_head);
  cmp(qword[rbx + lay.idle_skip], 0);
  jne(fail, T_NEAR);
  L(no_loop_head);
}

// guard()'s checks that depend on the run only through `needs` (kNeeds*).
void Impl::machine_checks(u32 needs, Label& fail, bool framed) {
  state_checks(fail);
  needs_checks(needs, fail, framed);
}

// The checks that hold for every run alike: no stop, no hook armed, time before the deadline, no
// load entering the pipeline, no DCIC code break, no pending interrupt, the i-cache enabled. Only
// a stop, the deadline and a hook armed by a branch change while native code runs, so a block
// whose native run reaches its end vouches for the rest to the block it chains to (chain(true)).
// Always the same code (fixed-size encodings and near jumps), padded to kStateCheckBytes at a
// block's entry.
void Impl::state_checks(Label& fail) {
  cmp(word[rbx + lay.stop], 0);  // stop_ and hook_armed_ together (Layout)
  jne(fail, T_NEAR);
  cmp(now, deadline);
  jae(fail, T_NEAR);
  cmp(cpu64(lay.new_load_reg), 0);  // new_load_reg_ and new_load_val_ together (Layout)
  jne(fail, T_NEAR);
  test(cpu32(lay.dcic), Cop0::kDcicPCE);
  jnz(fail, T_NEAR);
  Label interrupts_off, no_irq;
  mov(eax, cpu32(lay.sr));  // CpuT::interrupt_pending()
  test(eax, Cop0::kIEc);
  jz(interrupts_off);
  mov(ecx, cpu32(lay.cause));
  and_(ecx, 0x300);
  mov(rdx, reinterpret_cast<u64>(lay.irq_stat));
  mov(edx, dword[rdx]);
  mov(rsi, reinterpret_cast<u64>(lay.irq_mask));
  test(dword[rsi], edx);
  jz(no_irq);
  or_(ecx, Cop0::kIP2);
  L(no_irq);
  and_(ecx, eax);
  test(ecx, 0xFF00);
  jnz(fail, T_NEAR);
  L(interrupts_off);
  mov(rax, reinterpret_cast<u64>(lay.cache_control));
  test(dword[rax], lay.icache_enable);
  jz(fail, T_NEAR);
}

// The checks a run's instructions ask for: no DCIC data break for memory accesses, SR.CU2 for
// the GTE's, and memory_guard(). In the frame (`framed`: not in a routine), they are skipped where
// the frame's vouch byte (kVouched) says that all of them held since the last call, and where all
// of them hold, the byte is set: only a step's call can change what they check (SR, DCIC, the
// cache control, watches; the GTE's and the code pages' calls change none of it), and the step
// routine, which makes every step's call, clears the byte. Blocks chained to one another mostly
// skip the checks then (Tumble: 1.497 -> 1.482 G instructions in 100 moves).
void Impl::needs_checks(u32 needs, Label& fail, bool framed) {
  if (!framed || needs == 0) return specific_needs_checks(needs, fail);
  Label &vouched = cold_label(), &specific = cold_label();
  cmp(byte[rsp + kVouched], 0);
  jne(vouched, T_NEAR);
  specific_needs_checks(kNeedsMemory | kNeedsStores | kNeedsCop2, specific);
  mov(byte[rsp + kVouched], 1);
  L(vouched);
  cold.push_back([this, needs, &fail, &specific, &vouched] {
    L(specific);  // some check of the full set fails: this run may need fewer
    specific_needs_checks(needs, fail);
    jmp(vouched, T_NEAR);
  });
}

void Impl::specific_needs_checks(u32 needs, Label& fail) {
  if (needs & kNeedsMemory) {
    test(cpu32(lay.dcic), Cop0::kDcicDAE);
    jnz(fail, T_NEAR);
  }
  if (needs & kNeedsCop2) {
    test(cpu32(lay.sr), Cop0::kCU2);  // else the GTE instructions raise Coprocessor Unusable
    jz(fail, T_NEAR);
  }
  if (needs & kNeedsMemory) memory_guard((needs & kNeedsStores) != 0, fail);
}

void Impl::pad_to(size_t start, size_t bytes, const char* what) {
  const size_t used = getSize() - start;
  if (used > bytes)
    throw std::logic_error(std::string("recompiler: ") + what + " longer than reserved (" + std::to_string(used) +
                           " bytes)");
  nop(bytes - used);
}

// machine_checks() as a routine of the block (emitted once per `needs` with the cold code),
// for the re-guards after slow calls: called, it answers with ZF set when every check holds.
// Nothing in it calls out, so the stack needs no alignment.
Label& Impl::machine_routine(u32 needs) {
  Label*& r = routines[needs];
  if (!r) {
    r = &cold_label();
    cold.push_back([this, needs, &entry = *r] {
      Label fail;
      L(entry);
      machine_checks(needs, fail, false);
      xor_(eax, eax);  // ZF set: the checks hold
      ret();
      L(fail);
      or_(eax, 1);  // ZF clear
      ret();
    });
  }
  return *r;
}

// Instruction k of a native segment: CpuT::run()'s loop pass and execute_at_pc(). The guard
// has checked what no instruction of the segment can change (stop, hooks, interrupts, loop
// heads, debug breaks, i-cache hits, new_load_* zero), so only time needs a check before each
// instruction after the first, which the guard's budget_check() has made for all of them, and
// the i-cache where one starts a line the guard left to it. A branch may arm a hook or name a
// loop head, but only its delay slot follows it in the segment, and step() leaves an armed hook
// alone in a delay slot, and the loop head lies at or before the branch. The guard has also
// seen that the first instruction is not in a delay slot, so where each instruction is and goes
// is known (but for a delay slot's target), and the load delay slot is as seg.pipe[k] says
// (unknown at the first instruction).
// A branch's delay slot (after_branch) runs with in_delay_slot_ set and goes wherever the
// branch set next_pc_. A load or store first checks, before changing anything, that it can make
// its access natively; if not, it runs as a call (seg.fallback[k]; see emit() for what follows).
void Impl::native(std::span<const Step> rest, size_t k, bool after_branch, Segment& seg) {
  using namespace cpu_detail;
  const Step& s = rest[0];
  const NativeOp op = s.native;
  const Pipe& pipe = seg.pipe[k];
  if (k == 0) {  // after the guard
    eax_reg = 0;
    owed = 0;
  }
  seg.eax_at[k] = eax_reg;
  seg.time_in[k] = owed;
  // A new i-cache line: its words must hit (guard()), else this instruction runs as a call,
  // which fetches (and fills) it.
  if (k > 0 && (s.pc & 15) == 0) line_check(rest, seg.slow_native[k], fill_entry(s.pc, seg, k), &seg.filled[k]);
  if (s.io != 0) io_address_check(s, seg.fallback[k]);
  else if (is_memory(op)) address_checks(op, s.word, seg.fallback[k]);
  if (after_branch && !quiet_delay) {  // else sync_pc()
    mov(cpu32(lay.current_pc), s.pc);
    mov(byte[rbx + lay.in_delay_slot], 1);
    if (!delay_dest) mov(byte[rbx + lay.next_in_delay], 0);  // a split branch left it so
  } else if (k == 0) {  // not in a delay slot (a split one on the way on wrote none: quiet_delay)
    mov(byte[rbx + lay.in_delay_slot], 0);
  }
  ++owed;  // the instruction's cycle
  shadow(s, k, seg);
  if (uses_time(op)) settle();
  const bool split = (seg.split && k + 2 == seg.count) || seg.mid[k];  // a split branch (Segment)
  const bool writes_pc = after_branch && !quiet_delay;
  if (const auto dest = delay_dest ? delay_dest : jump_dest; writes_pc && dest) {
    mov(cpu32(lay.pc), *dest);
    mov(cpu32(lay.next_pc), *dest + 4);
  } else if (writes_pc) {
    mov(eax, cpu32(lay.next_pc));
    mov(cpu32(lay.pc), eax);
    add(eax, 4);
    mov(cpu32(lay.next_pc), eax);
    eax_reg = 0;
  } else if (is_branch(op) && !split && op != NativeOp::Jr && op != NativeOp::Jalr) {
    mov(cpu32(lay.next_pc), s.pc + 8);  // a branch not taken leaves it so (JR and JALR write their target)
  }
  const u32 d = dest(op, s.word);
  if (is_branch(op)) branch(op, s.pc, s.word, split);
  else if (s.io != 0) io_access(rest, k);
  else if (is_load(op)) load(op, s.word, pipe, seg.shadow[k] != Shadow::check);
  else if (is_store_or_swc2(op)) store(op, s.word);
  else if (op == NativeOp::Lwc2) lwc2(s.word);
  else if (op >= NativeOp::Mfhi && op <= NativeOp::Mtlo) hilo(op, s.word);
  else if (op >= NativeOp::Mult && op <= NativeOp::Divu) muldiv(op, s.word);
  else if (is_cop2(op)) cop2(op, s.word);
  else if (d != 0) alu(op, s.word);  // an ALU operation into r0 (a NOP) changes nothing
  if (d != 0) mov(reg(d), eax);
  if (pipe.dynamic) keep_split_flags();  // commit() compares
  commit(pipe, is_delayed(op) ? rt(s.word) : d, is_delayed(op), rt(s.word), keeps_r10(op), seg.lazy[k],
         k > 0 && seg.lazy[k - 1]);  // leaves eax
  eax_reg = d;
  if (s.io != 0 && k + 1 < seg.count) io_checks(rest, k, seg);
}

// current_pc_, pc_ and next_pc_ after instruction j of a segment, which native code writes only
// where someone outside the block can look (sync_pc() at a segment's end, before a slow or
// fallback call, at a deadline exit): a delay slot writes its own, which depend on where the
// branch went, except the one of a branch split inside the segment (seg.mid), whose way on is
// the segment's rest: its values are those of any other instruction, with in_delay_slot_ set
// (quiet_delay). Any other instruction's are its address, the next and the one after, except
// that a branch has set next_pc_ itself. Nothing called from inside an instruction reads them
// (the GTE, the code pages).
void Impl::sync_pc(std::span<const Step> run, size_t j, const Segment& seg) {
  const bool delay_slot = j > 0 && is_branch(run[j - 1].native);
  if (delay_slot && !seg.mid[j - 1]) return;
  mov(cpu32(lay.current_pc), run[j].pc);
  mov(cpu32(lay.pc), run[j].pc + 4);
  if (!is_branch(run[j].native)) mov(cpu32(lay.next_pc), run[j].pc + 8);
  if (delay_slot) mov(byte[rbx + lay.in_delay_slot], 1);
}

// Six callee-saved pushes and 8 bytes more leave the stack 16-byte aligned at each call, as the
// ABI wants (the return address made it 8 off). Padded to kPrologueBytes, where a block linked
// from another (chain()) enters with the frame made and the registers loaded: every block of
// an emitter runs the same CPU on the same scheduler.
void Impl::prologue(const Layout& layout) {
  const size_t start = getSize();
  for (const Xbyak::Reg64& r : {rbx, r12, r13, r14, r15, rbp}) push(r);
  sub(rsp, 8);
  // The frame's spare bytes: no guard passed yet (chain()), no needs vouched for (needs_checks()).
  mov(word[rsp], 1);
  mov(rbx, reinterpret_cast<u64>(layout.context) + layout.bias);
  mov(r12, reinterpret_cast<u64>(layout.icache_tags));
  reload();
  pad_to(start, kPrologueBytes, "block prologue");  // at most 63 bytes (the longest encodings)
}

void Impl::epilogue() {
  add(rsp, 8);
  for (const Xbyak::Reg64& r : {rbp, r15, r14, r13, r12, rbx}) pop(r);
}

// A segment's labels and what each instruction knows when it starts: the load delay slot
// (Pipe), the load shadow (Shadow) and the deadline's budget.
void Impl::plan(std::span<const Step> run, Segment& seg) {
  for (auto* v : {&seg.slow, &seg.fallback, &seg.resume, &seg.stall, &seg.stall_back, &seg.fill, &seg.filled,
                  &seg.slow_native})
    *v = std::vector<Label>(seg.count);
  seg.pipe.assign(seg.count, Pipe{});
  seg.eax_at.assign(seg.count, 0);
  seg.time_in.assign(seg.count, 0);
  seg.stall_owed.assign(seg.count, 0);
  seg.lazy.assign(seg.count, false);
  for (size_t k = 1; k < seg.count; ++k) {
    seg.pipe[k] = {false, is_delayed(run[k - 1].native), cpu_detail::rt(run[k - 1].word)};
    // (Not before an I/O load, whose call sees the pipeline in memory.)
    seg.lazy[k - 1] = is_delayed(run[k - 1].native) && lazy_lands(run[k].native) && run[k].io == 0;
  }
  plan_shadow(run, u32(lay.load_issue + lay.load_bus - 1), seg.shadow, seg.shadowed);
  // Branches with their delay slot and more of the segment after them split (compile() went on
  // past them only where they do, BlockEmitter::goes_on()).
  seg.mid.assign(seg.count, false);
  for (size_t k = 0; k + 2 <= seg.count; ++k) {
    if (!is_branch(run[k].native) || (k + 2 == seg.count && seg.ends_block)) continue;
    if (!splits_at(run, k, seg.shadow, seg.shadowed))
      throw std::logic_error("recompiler: a block goes on past a branch it cannot split");
    seg.mid[k] = true;
  }
  // budget[k]: waits and cycles of instructions k .. count - 2 (none for the last instruction).
  seg.budget.assign(seg.count, 0);
  for (u32 k = u32(seg.count) - 1, cycles = 0, wait = 0; k-- > 0;) {
    cycles += most_cycles(run, k);
    wait = std::max(wait, longest_wait(run[k]));
    seg.budget[k] = cycles + wait;
  }
}

// Off a segment's main path: an instruction the native code could not run (slow[k]: the guard
// or a line check refused; fallback[k]: a load or store the native code does not make) runs as
// its call, and the segment goes on natively from the next one if the guard allows it then (a
// refusal is often over after one instruction: a cold i-cache line filled by its first fetch, a
// load landing), else by the next instruction's slow path. Only the slow path's entries from
// native code (the segment's start, a line's start) re-guard: a refusal that outlasts one
// instruction mostly outlasts the line, and each re-guard is code to emit. The call leaves the
// pipeline as the native code would have (a load pending in rt, or none), so seg.pipe holds
// after it too. Then the entries from a line check's refusal, the shadow stalls and the i-cache
// fills.
void Impl::segment_stubs(std::span<const Step> run, Segment& seg) {
  for (size_t k = 0; k < seg.count; ++k) {
    L(seg.slow[k]);
    if (k > 0) sync_pc(run, k - 1, seg);  // from native code (or the call before: the same values)
    // A split branch has no native delay slot to resume (split_end()): on into its slow path.
    const bool split_branch = (seg.split && k + 2 == seg.count) || seg.mid[k];
    if (!split_branch && (k == 0 || (run[k].pc & 15) == 0 || k + 1 == seg.count)) {
      call_and_resume(run, k, seg);
    } else {
      call_step(run[k]);  // on into slow[k + 1]
    }
  }
  for (size_t k = 0; k < seg.count; ++k) {
    if (!is_memory(run[k].native)) continue;
    L(seg.fallback[k]);
    pending(run, k, seg);
    if (seg.time_in[k] != 0) add(now, int(seg.time_in[k]));
    if (k > 0) {
      add(instructions, int(k));
      sync_pc(run, k - 1, seg);
    }
    call_and_resume(run, k, seg);
  }
  for (size_t k = 1; k < seg.count; ++k) {
    if ((run[k].pc & 15) != 0) continue;  // a line check's or a fill's refusal
    L(seg.slow_native[k]);
    pending(run, k, seg);
    if (seg.time_in[k] != 0) add(now, int(seg.time_in[k]));
    add(instructions, int(k));
    jmp(seg.slow[k], T_NEAR);
  }
  for (size_t k = 0; k < seg.count; ++k) {
    if (has_stall(run[k], seg, k)) stall_stub(k, seg);
    if ((k == 0 || (run[k].pc & 15) == 0) && fills_natively(run[k].pc)) fill_stub(run.subspan(k), k, seg);
  }
}

// Instruction k as its call, then back to native code at k + 1 if the guard holds for the rest.
void Impl::call_and_resume(std::span<const Step> run, size_t k, Segment& seg) {
  call_step(run[k]);
  if (k + 1 == seg.count) {
    jmp(seg.end, T_NEAR);
    return;
  }
  guard(run.subspan(k + 1), seg.slow[k + 1], Checks::routine, seg.budget[k + 1]);
  if (seg.eax_at[k + 1] != 0) mov(eax, reg(seg.eax_at[k + 1]));  // as native code left it
  if (seg.pipe[k + 1].after_load) mov(r10d, cpu32(lay.load_val));
  if (seg.lazy[k]) {  // the call's load as a lazy one (Segment::lazy)
    mov(cpu32(lay.load_reg), 0);
    mov(cpu32(lay.load_val), 0);
  }
  sub(instructions, int(k + 1));  // native code counts from where it resumes
  if (seg.time_in[k + 1] != 0) sub(now, int(seg.time_in[k + 1]));  // and owes what it owed there
  if (loops_natively) mov(byte[rsp], 1);  // a call since the block's guard (chain())
  // Instruction 0 may have been a delay slot whose branch went on to instruction 1, which then
  // is not in one: native code writes in_delay_slot_ at instruction 0 only (or after a branch).
  if (k == 0 && !is_branch(run[0].native)) mov(byte[rbx + lay.in_delay_slot], 0);
  jmp(seg.resume[k + 1], T_NEAR);
}

BlockEmitter::BlockEmitter(size_t buffer_bytes) : impl_(std::make_unique<Impl>(buffer_bytes)) {}
BlockEmitter::~BlockEmitter() = default;

BlockEmitter::BlockFn BlockEmitter::emit(const Layout& layout, std::span<const Step> steps) {
  // Upper bounds on one step's code (inline code with a line check, stall stub, and the slow
  // call and the load's or store's call, each with the guard for the rest: at most about 180
  // bytes and a line check of at most 90) and on the frame's (prologue and padded checks,
  // kCleanEntry bytes, then up to three chain()s of about 250 bytes each, two of them after a
  // split branch, and the loop-head routine).
  // The fill routines, when this block emits them first, take about 800 bytes.
  const size_t step_bytes = 1536, frame_bytes = 1536 + (impl_->fill_routines[0] ? 0 : 1024);
  Impl& g = *impl_;
  if (g.getSize() + frame_bytes + step_bytes * steps.size() > g.capacity) return nullptr;
  g.lay = layout;
  Label done;
  g.exit = &done;
  g.routines.fill(nullptr);
  g.step_entry = nullptr;
  g.loop_head_entry = nullptr;
  g.split_cond.reset();
  g.jump_dest.reset();
  g.links.clear();
  const bool had_routines = g.fill_routines[0] != nullptr;
  g.fill_routines_once();
  const size_t routines_end = g.getSize();
  g.align(16);
  const auto entry = g.getCurr<BlockFn>();
  g.block_pc = steps[0].pc;
  g.ends_in_branch = Impl::is_branch(steps.back().native);
  g.aligned_end = steps.size() < 2 || !cpu_detail::jumps_by_register(steps[steps.size() - 2].word);
  g.block_entry = g.getCurr();
  g.self_loop = std::any_of(steps.begin(), steps.end(), [&](const Step& s) {
    return Impl::is_branch(s.native) && s.native != NativeOp::Jr && s.native != NativeOp::Jalr &&
           Impl::static_target(s.native, s.pc, s.word) == steps[0].pc;
  });
  g.loops_natively = g.self_loop && std::all_of(steps.begin(), steps.end(), [](const Step& s) {
    return s.native != NativeOp::None;
  });
  const size_t start = g.getSize();
  g.prologue(layout);
  if (steps[0].native == NativeOp::None) {  // no guard: both chained entries go to the first call
    Label first;
    g.jmp(first, Xbyak::CodeGenerator::T_NEAR);
    g.pad_to(start, Impl::kCleanEntry, "block entry");
    g.L(first);
  }
  std::vector<Segment> segments;
  segments.reserve(steps.size());  // labels must not move once used
  for (size_t i = 0; i < steps.size();) {
    if (steps[i].native == NativeOp::None) {
      g.call_step(steps[i++]);
      continue;
    }
    Segment& seg = segments.emplace_back();
    seg.first = i;
    while (i < steps.size() && steps[i].native != NativeOp::None) ++i;
    seg.count = i - seg.first;
    const std::span<const Step> run = steps.subspan(seg.first, seg.count);
    seg.ends_block = i == steps.size();
    g.plan(run, seg);
    // A run of one instruction checks no deadline within it.
    const std::optional<u32> budget = seg.count > 1 ? std::optional<u32>(seg.budget[0]) : std::nullopt;
    g.guard(run, seg.slow[0], seg.first == 0 ? Impl::Checks::entry : Impl::Checks::all, budget,
            g.fill_entry(run[0].pc, seg, 0), &seg.filled[0]);
    seg.split = seg.ends_block && g.splits(run, seg);
    for (size_t k = 0; k < seg.count - (seg.split ? 1 : 0); ++k) {
      const bool after_branch = k > 0 && Impl::is_branch(run[k - 1].native);
      if (after_branch && seg.mid[k - 1]) continue;  // emitted for each way by split_mid()
      const NativeOp before = k > 0 ? run[k - 1].native : NativeOp::None;
      if (after_branch && k + 1 == seg.count && (before == NativeOp::J || before == NativeOp::Jal))
        g.jump_dest = Impl::static_target(before, run[k - 1].pc, run[k - 1].word);
      g.L(seg.resume[k]);
      g.native(run.subspan(k), k, after_branch, seg);
      if (seg.mid[k]) g.split_mid(run, seg, k, budget);
    }
    if (seg.split) {
      g.split_end(run, seg, budget);
    } else {
      g.settle();
      g.add(g.instructions, int(seg.count));
      g.sync_pc(run, seg.count - 1, seg);
      if (seg.ends_block)  // the block's native end
        g.chain(true, g.loops_natively ? &seg.resume[0] : nullptr, budget, g.jump_dest);
    }
    g.jump_dest.reset();
    g.L(seg.end);
  }
  g.L(done);
  g.chain(false);
  for (Segment& seg : segments) g.segment_stubs(steps.subspan(seg.first, seg.count), seg);
  g.emit_cold();
  last_ = {};
  if (!had_routines && g.fill_routines[0]) {
    last_.routines = g.fill_routines[0];
    last_.routine_bytes = routines_end - size_t(g.fill_routines[0] - g.getCode());
  }
  last_.block_bytes = g.getSize() - start;
  last_.links = std::move(g.links);
  return entry;
}

void Impl::emit_cold() {
  for (const auto& f : cold) f();
  cold.clear();
  cold_labels.clear();
}

void BlockEmitter::clear() {
  impl_->reset();
  impl_->fill_routines.fill(nullptr);
}

size_t BlockEmitter::bytes_used() const { return impl_->getSize(); }

}  // namespace psx
