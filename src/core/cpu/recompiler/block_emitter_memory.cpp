// Native loads, stores, the load delay slot and HI/LO moves for compiled blocks (emitter_impl.h):
// CpuT::load(), load_unaligned(), store(), store_unaligned(), timed_read() and wait_muldiv(), and
// LWC2/SWC2 for the accesses the native code makes itself, to RAM (its 2 MiB through the first
// 8 MiB of KUSEG, KSEG0 and KSEG1, as Bus::read/write map it) and to the scratchpad (KUSEG and
// KSEG0). Everything else about an access (an address error, user mode, a debug data break armed,
// an isolated cache for a store, D-cache mode, memory watches, I/O and the other regions) sends
// the instruction to its call step.
#include "core/bus.h"
#include "core/cpu/cop0.h"
#include "core/cpu/decode.h"
#include "core/cpu/icache.h"
#include "core/cpu/recompiler/code_pages.h"
#include "core/cpu/recompiler/emitter_impl.h"

namespace psx {

using Xbyak::Label;
using Impl = BlockEmitter::Impl;

namespace {

constexpr u32 kRamMask = CodePages::kRamSize - 1;
constexpr u32 kScratchBase = 0x1F800000, kScratchMask = 0x3FF;
// Past address_checks(), r13d is the access's offset from Layout::ram: RAM's byte, or for the
// scratchpad, which follows RAM there (Bus::scratchpad()), kRamSize plus its byte.
constexpr u32 kAreaBytes = CodePages::kRamSize + CodePages::kScratchBytes;
constexpr u32 kScratchOffset = CodePages::kRamSize;
// Address bits that must be zero for RAM (below 8 MiB within the 512 MiB segment).
constexpr u32 kNotRam = 0x1F800000;
// Address bits that must be zero for the RAM the main path takes: the first 8 MiB of KUSEG or
// KSEG0 (segments 0 and 4: bits 30-23 clear). KSEG1's RAM (segment 5: bit 29 set) and the
// scratchpad take the cold path, which sends the rest to the call step.
constexpr u32 kNotCachedRam = 0x7F800000;

}  // namespace

// What guard() checks once for a segment with loads or stores, because no native instruction
// changes it: the accesses the native code makes need kernel mode (user mode may raise an
// address error), no D-cache mode (loads would fill the scratchpad), and for stores neither an
// isolated cache nor memory watches (DCIC's data break is checked with its other bits).
void Impl::memory_guard(bool stores, Label& fail) {
  test(cpu32(lay.sr), stores ? Cop0::kKUc | Cop0::kIsC : Cop0::kKUc);
  jnz(fail, T_NEAR);
  mov(rax, reinterpret_cast<u64>(lay.dcache_mode));
  cmp(byte[rax], 0);
  jne(fail, T_NEAR);
  if (stores) {
    mov(rax, reinterpret_cast<u64>(lay.watches));
    cmp(qword[rax], 0);
    jne(fail, T_NEAR);
  }
}

// r13d = the address (rs + offset). Before the instruction changes anything, whether its access
// is one the native code makes (past memory_guard()): aligned (LWL/LWR/SWL/SWR need not be), and
// RAM or the scratchpad. Then r13d becomes the access's offset from Layout::ram (kAreaBytes):
// nothing after this reads the address, and the offset keeps its low two bits.
void Impl::address_checks(NativeOp op, u32 i, Label& slow) {
  using namespace cpu_detail;
  const u32 width = access_width(op);
  with_reg(rs(i), [&](const Xbyak::Operand& o) { mov(r13d, o); });
  if (simm(i) != 0) add(r13d, simm(i));
  // One test on the main path: aligned, and KUSEG's or KSEG0's RAM.
  Label &not_ram = cold_label(), &ok = cold_label();
  test(r13d, kNotCachedRam | (width - 1));
  jnz(not_ram, T_NEAR);
  and_(r13d, kRamMask);
  L(ok);
  cold.push_back([this, &not_ram, &ok, &slow, width] {
    Label not_kseg1;
    L(not_ram);
    if (width > 1) {
      test(r13d, width - 1);
      jnz(slow, T_NEAR);
    }
    mov(ecx, r13d);
    shr(ecx, 29);  // the segment: 0-3 KUSEG, 4 KSEG0, 5 KSEG1, 6-7 KSEG2
    cmp(cl, 5);    // KSEG1's RAM: its first 8 MiB
    jne(not_kseg1);
    test(r13d, kNotRam);
    jnz(slow, T_NEAR);
    and_(r13d, kRamMask);
    jmp(ok, T_NEAR);
    L(not_kseg1);
    test(cl, 3);  // the scratchpad: KUSEG or KSEG0 (segment 0 or 4) ...
    jnz(slow, T_NEAR);
    mov(edx, r13d);
    and_(edx, 0x1FFFFFFF & ~kScratchMask);  // ... at physical 1F800000h-1F8003FFh
    cmp(edx, kScratchBase);
    jne(slow, T_NEAR);
    and_(r13d, kScratchMask);
    or_(r13d, kScratchOffset);
    jmp(ok, T_NEAR);
  });
}

// Where native code finds the byte at offset `index` (zero-extended) of Layout::ram's RAM and
// scratchpad: rbx-relative where the whole area lies within a signed 32-bit displacement of the
// context (one instruction fewer), else through rdx, loaded here. LWL/LWR/SWL/SWR, which also
// reach the word through other index registers, always take rdx.
Xbyak::RegExp Impl::host_at(const Xbyak::Reg64& index, bool via_rdx) {
  const auto d = from_context(lay.ram);
  if (!via_rdx && d && from_context(lay.ram + kAreaBytes)) return rbx + index + *d;
  mov(rdx, reinterpret_cast<u64>(lay.ram));
  return rdx + index;
}

// Where `op` accesses RAM or the scratchpad (r13d: address_checks()): LWL/LWR/SWL/SWR the word
// holding the address (its offset in rcx, which they also use), the rest the address itself.
Xbyak::RegExp Impl::word_at(NativeOp op) {
  if (!is_unaligned(op)) return host_at(r13, false);
  mov(ecx, r13d);
  and_(ecx, ~3u);
  return host_at(rcx, true);
}

// eax = the value a load of `op`'s width and signedness reads at `at`.
static void read_width(Impl& g, NativeOp op, const Xbyak::RegExp& at) {
  switch (op) {
    case NativeOp::Lb: g.movsx(g.eax, g.byte[at]); break;
    case NativeOp::Lbu: g.movzx(g.eax, g.byte[at]); break;
    case NativeOp::Lh: g.movsx(g.eax, g.word[at]); break;
    case NativeOp::Lhu: g.movzx(g.eax, g.word[at]); break;
    default: g.mov(g.eax, g.dword[at]); break;
  }
}

// CpuT::load() past its checks: timed_read() and the value (eax). From RAM by cached code (the
// guard's i-cache hits are cached code) the load-shadow arithmetic: the access starts when the
// load has issued or the previous access ends (a cycle later for a load in the delay slot of a
// load to the same register), the CPU waits only until it starts, and rt is shadowed until it
// ends. From the scratchpad: wait_load(), then a read without time. `bus_free`: the load's shadow
// check is known to find the previous access over (plan_shadow(): time has reached its end), so
// the access starts as the load issues and neither path waits; the main path's extra cycles
// stay owed (Impl::owed), and the scratchpad's path takes them back.
void Impl::load(NativeOp op, u32 i, const Pipe& pipe, bool bus_free) {
  const u32 t = cpu_detail::rt(i);
  Label &scratchpad = cold_label(), &done = cold_label();
  test(r13d, kScratchOffset);
  jnz(scratchpad, T_NEAR);
  if (bus_free) {
    lea(rcx, ptr[now + lay.load_issue + lay.load_bus]);
  } else {
    lea(rcx, ptr[now + lay.load_issue]);  // issue_end + 1
    mov(rdx, cpu64(lay.load_done_at));
    if (t != 0 && pipe.dynamic) {
      xor_(eax, eax);
      cmp(cpu32(lay.load_reg), t);
      sete(al);
      add(rdx, rax);
    } else if (t != 0 && pipe.after_load && pipe.load_reg == t) {
      add(rdx, 1);
    }
    cmp(rcx, rdx);
    cmovb(rcx, rdx);  // the access's start
    lea(now, ptr[rcx - 1]);
    add(rcx, lay.load_bus);
  }
  mov(cpu64(lay.load_done_at), rcx);
  mov(cpu32(lay.shadow_reg), t);
  read_width(*this, op, word_at(op));
  L(done);
  const u32 issue = bus_free ? u32(lay.load_issue - 1) : 0;
  owed += issue;
  cold.push_back([this, &scratchpad, &done, op, issue] {
    L(scratchpad);
    if (issue != 0) {
      sub(now, int(issue));
    } else {
      mov(rcx, cpu64(lay.load_done_at));
      cmp(now, rcx);
      cmovb(now, rcx);
    }
    read_width(*this, op, word_at(op));
    jmp(done, T_NEAR);
  });
  if (is_unaligned(op)) merge_unaligned(op, t, pipe);
}

// A native I/O load's or store's address (r13d) against its port (Step::io): any other address
// takes the instruction's call (`slow`), which makes whatever access that is. The guard's memory
// checks hold (kernel mode, no D-cache mode, no DCIC data break; for a store, no isolated cache or
// memory watch) and the port's address is aligned, so the access passes CpuT::load()'s or
// store()'s checks.
void Impl::io_address_check(const Step& s, Label& slow) {
  using namespace cpu_detail;
  with_reg(rs(s.word), [&](const Xbyak::Operand& o) { mov(r13d, o); });
  if (simm(s.word) != 0) add(r13d, simm(s.word));
  cmp(r13d, s.io);
  jne(slow, T_NEAR);
}

// CpuT::load() or store() past its checks for a native I/O access (instruction k of the segment):
// one call makes a load's timed_read() wait and the port's read (RecompilerT::io_load()), or a
// store's write of rt as it is before the pending load lands (io_store()). Either may run events
// (and a store, DMA). Those see the CPU as the interpreter leaves it during the access, as they
// would during a step's call: the time (r14, with this instruction's cycle) and the count (with
// this instruction), the pc's fields (sync_pc()'s, and no delay slot: the recompiler makes no I/O
// access native in one), the pipeline (plan() keeps the load before this one out of r10 alone)
// and the load shadow (shadow() checks it here as at a segment's last instruction). The call
// leaves a load's value in eax and whether the CPU must leave native code in r9d (io_checks()).
// r10, a load landing, is kept across it. The call for a load knows where the port's bus tail
// ends as far as the words compiled tell (tail_plan()).
void Impl::io_access(std::span<const Step> rest, size_t k) {
  const Step& s = rest[0];
  settle();  // a load's is made already (uses_time())
  const bool store = is_store(s.native);
  if (store) {
    read_eax(cpu_detail::rt(s.word));
    mov(edx, eax);
  }
  mov(cpu32(lay.current_pc), s.pc);
  mov(cpu32(lay.pc), s.pc + 4);
  mov(cpu32(lay.next_pc), s.pc + 8);
  mov(byte[rbx + lay.in_delay_slot], 0);
  mov(byte[rbx + lay.next_in_delay], 0);
  add(instructions, int(k + 1));
  push(r10);
  sub(rsp, 8);  // the stack's alignment at a call
  flush();
  lea(rdi, ptr[rbx - lay.bias]);
  mov(esi, r13d);
  if (store) call_leaf(reinterpret_cast<const void*>(lay.io_stores[u32(s.native) - u32(NativeOp::Sb)]));
  else call_io_load(s, tail_plan(rest));
  reload();
  add(rsp, 8);
  pop(r10);
  sub(instructions, int(k + 1));
  mov(r9, rax);
  shr(r9, 32);
}

// What CpuT::io_tail() would find of the two instructions after the I/O load rest[0], from the
// words compiled where the i-cache is known to hold them. On the load's own line: that line's
// check (line_check(), by the guard or at the line's first instruction) found every word of the
// run on it a hit holding the word compiled, and nothing up to the load's tail changes that (the
// i-cache changes by the CPU's fetches and stores alone; io_checks()). On the next line, where
// its check is still to come: when that line is whole and not stale (call_io_load() tests it),
// as line_check() reasons. Past the next line or the segment, the call looks itself.
Impl::TailPlan Impl::tail_plan(std::span<const Step> rest) {
  using namespace cpu_detail;
  const u32 line = rest[0].pc & ~15u;
  TailPlan plan;
  const auto known = [&](size_t n) {
    if (n >= rest.size() || rest[n].pc != rest[0].pc + 4 * n) return false;
    if ((rest[n].pc & ~15u) == line) return true;
    if ((rest[n].pc & ~15u) != line + 16) return false;
    plan.next_line = line + 16;
    return true;
  };
  if (!known(1)) return {};
  const u32 t = rt(rest[0].word);  // its reader second meets the tail (CpuT::meets_tail())
  const auto meets = [&](u32 w) { return loads_memory(w) || (t != 0 && reads_reg(w, t)); };
  if (loads_memory(rest[1].word)) plan.reach = 1;
  else plan.reach = known(2) ? (meets(rest[2].word) ? 2 : 3) : kTailPastFirst;
  return plan;
}

// The call of RecompilerT::io_load() for the I/O load s (edx: its rt), with the tail's reach that `plan`
// gives, or, where the plan needs the next line and that line is not whole (a miss or a part
// of the line) or stale, with the reach the call finds itself.
void Impl::call_io_load(const Step& s, const TailPlan& plan) {
  const auto* row = lay.io_loads[u32(s.native) - u32(NativeOp::Lb)];
  mov(rax, reinterpret_cast<u64>(row[plan.reach]));
  if (plan.next_line) {
    mov(rcx, reinterpret_cast<u64>(row[cpu_detail::kTailUnknown]));
    cmp(icache_tag(*plan.next_line), (Bus::physical(*plan.next_line) & ICache::kTagMask) | 0xF);
    cmovne(rax, rcx);
  }
  mov(edx, cpu_detail::rt(s.word));
  call(rax);
}

// After a native I/O access (instruction k), the guard's checks for the instructions after it that
// the call may have changed: the CPU stopped, a hook armed or an interrupt pending (r9d, from
// io_access()), and the deadline for the rest (the access's time, a DMA's, or an event booked
// sooner). The rest the port and the events during the call cannot change (guard()); not the
// i-cache either, which only the CPU's fetches and stores fill and tag: code a DMA writes marks
// its lines stale (ICache::kStale), but they still hold the words compiled, which the native run
// goes on with as the interpreter would. Failing, on to instruction k + 1's slow path, with a
// load pending as commit() left it.
void Impl::io_checks(std::span<const Step> rest, size_t k, Segment& seg) {
  Label& fail = cold_label();
  test(r9d, r9d);
  jnz(fail, T_NEAR);
  budget_check(seg.budget[k + 1], fail);
  cold.push_back([this, &fail, &seg, k, rt = cpu_detail::rt(rest[0].word)] {
    L(fail);
    if (seg.lazy[k]) {  // pending() for k + 1
      mov(cpu32(lay.load_reg), rt);
      mov(cpu32(lay.load_val), r10d);
    }
    add(instructions, int(k + 1));
    jmp(seg.slow[k + 1], T_NEAR);
  });
}

// CpuT::load_unaligned()'s merge of the word read (eax) into rt's value, which is the value of a
// load to rt still in its delay slot (load_reg_ == rt: load_val_) rather than the register.
// LWL puts the word's low (offset + 1) bytes in the top of rt, LWR its bytes from the offset on
// in the bottom.
void Impl::merge_unaligned(NativeOp op, u32 t, const Pipe& pipe) {
  mov(edx, reg(t));
  if (pipe.dynamic) {
    cmp(cpu32(lay.load_reg), t);
    cmove(edx, cpu32(lay.load_val));
  } else if (pipe.after_load && pipe.load_reg == t) {
    mov(edx, cpu32(lay.load_val));
  }
  mov(ecx, r13d);
  and_(ecx, 3);
  shl(ecx, 3);  // sh = offset * 8
  if (op == NativeOp::Lwl) {  // (cur & (00FFFFFFh >> sh)) | (word << (24 - sh))
    mov(r8d, 0x00FFFFFF);
    shr(r8d, cl);
    and_(edx, r8d);
    neg(ecx);
    add(ecx, 24);
    shl(eax, cl);
  } else {  // (cur & ~(FFFFFFFFh >> sh)) | (word >> sh)
    mov(r8d, 0xFFFFFFFF);
    shr(r8d, cl);
    not_(r8d);
    and_(edx, r8d);
    shr(eax, cl);
  }
  or_(eax, edx);
}

// CpuT::store_unaligned()'s bytes, written into the word at [rdx + rcx] (rcx kept) from the
// register's value (eax): SWL its top (offset + 1) bytes into the word's bytes 0..offset, SWR its
// low (4 - offset) bytes into bytes offset..3. Host memory takes them as one word.
static void store_unaligned(Impl& g, NativeOp op) {
  g.mov(g.r8, g.rcx);
  g.mov(g.ecx, g.r13d);
  g.and_(g.ecx, 3);
  g.shl(g.ecx, 3);  // offset * 8
  g.mov(g.r9d, 0xFFFFFFFF);
  if (op == NativeOp::Swl) {  // bytes 0..offset: mask FFFFFFFFh >> (24 - offset * 8)
    g.neg(g.ecx);
    g.add(g.ecx, 24);
    g.shr(g.r9d, g.cl);
    g.shr(g.eax, g.cl);
  } else {  // bytes offset..3: mask FFFFFFFFh << (offset * 8)
    g.shl(g.r9d, g.cl);
    g.shl(g.eax, g.cl);
  }
  g.not_(g.r9d);
  g.and_(g.r9d, g.dword[g.rdx + g.r8]);
  g.or_(g.eax, g.r9d);
  g.mov(g.dword[g.rdx + g.r8], g.eax);
  g.mov(g.rcx, g.r8);
}

// execute_at_pc()'s load delay slot after the instruction: the previous instruction's load
// lands unless this one wrote the register (write_reg and delayed_load clear load_reg_ for
// `cleared`), and this one's load (`load`: eax to rt) becomes the pending one. The value landing
// comes from r10d, which the load left there, where this instruction has not called out
// (`r10_kept`), else from load_val_.
// Where it is not known (a segment's first instruction), an empty slot (load_reg_ and load_val_
// both zero, which then stay so) is checked for and the rest left to the cold code.
// A `lazy` load (Segment::lazy) leaves load_reg_ and load_val_ zero, and where the load landing
// was lazy (`pending_lazy`) they are zero already.
void Impl::commit(const Pipe& pipe, u32 cleared, bool load, u32 rt, bool r10_kept, bool lazy,
                  bool pending_lazy) {
  if (pipe.dynamic) {
    Label &pending = cold_label(), &back = cold_label();
    cmp(cpu64(lay.load_reg), 0);  // load_reg_ and load_val_ together (Layout)
    jne(pending, T_NEAR);
    L(back);
    cold.push_back([this, &pending, &back, cleared, load, lazy] {
      Label skip;
      L(pending);
      mov(ecx, cpu32(lay.load_reg));
      if (cleared != 0) {
        cmp(ecx, cleared);
        je(skip);
      }
      mov(edx, cpu32(lay.load_val));
      mov(dword[rbx + rcx * 4 + lay.regs], edx);
      L(skip);
      mov(reg(0), 0);
      if (!load || lazy) {
        mov(cpu32(lay.load_reg), 0);
        mov(cpu32(lay.load_val), 0);
      }
      jmp(back, T_NEAR);
    });
  } else if (pipe.after_load && pipe.load_reg != 0 && pipe.load_reg != cleared) {
    if (r10_kept) {
      mov(reg(pipe.load_reg), r10d);
    } else {
      mov(edx, cpu32(lay.load_val));
      mov(reg(pipe.load_reg), edx);
    }
  }
  if (load && !lazy) {
    mov(cpu32(lay.load_reg), rt);
    mov(cpu32(lay.load_val), eax);
  } else if (pipe.after_load && !pending_lazy) {
    mov(cpu32(lay.load_reg), 0);
    mov(cpu32(lay.load_val), 0);
  }
  if (load) mov(r10d, eax);
}

// Whether an instruction after a load may land it from r10d with load_reg_ and load_val_ left
// zero (Segment::lazy): one that leaves r10 alone (keeps_r10()) and reads neither field itself
// (LWL/LWR merge with load_val_); its ways to a call write them first (pending()).
bool Impl::lazy_lands(NativeOp op) { return keeps_r10(op) && !is_unaligned(op); }

// Where native code leaves instruction k for its call while a lazy load (instruction k - 1) is
// pending: load_reg_ and load_val_ as the load would have left them.
void Impl::pending(std::span<const Step> run, size_t k, const Segment& seg) {
  if (k == 0 || !seg.lazy[k - 1]) return;
  mov(cpu32(lay.load_reg), cpu_detail::rt(run[k - 1].word));
  mov(cpu32(lay.load_val), r10d);
}

// CpuT::store() past its checks: Bus::write() to RAM or the scratchpad, its page marked written
// (WrittenPages::mark()), with CodePages::on_ram_write() called when the word holds compiled
// code. Stores take no time (the write queue).
void Impl::store(NativeOp op, u32 i) {
  const u32 width = access_width(op);
  Label& done = cold_label();
  if (op == NativeOp::Swc2) {  // SWC2: the GTE register, once the GTE is done
    wait_gte();
    if (const auto f = Gte::data_field(cpu_detail::rt(i), false)) {
      gte_read(*f);
    } else {
      mov(rdi, reinterpret_cast<u64>(lay.gte));
      mov(esi, cpu_detail::rt(i));
      call_leaf(reinterpret_cast<const void*>(lay.gte_read_data));
    }
  } else {
    read_eax(cpu_detail::rt(i));
  }
  const Xbyak::RegExp at = word_at(op);
  if (is_unaligned(op)) store_unaligned(*this, op);
  else if (width == 4) mov(dword[at], eax);
  else if (width == 2) mov(word[at], ax);
  else mov(byte[at], al);
  // The page is written (written_pages.h: the same pages as the code pages').
  mov(edx, r13d);
  shr(edx, CodePages::kPageBits);
  if (const auto d = from_context(lay.written_pages);
      d && from_context(lay.written_pages + CodePages::kPages + CodePages::kSparePages)) {
    mov(byte[rbx + rdx + *d], 1);
  } else {
    mov(rsi, reinterpret_cast<u64>(lay.written_pages));
    mov(byte[rsi + rdx], 1);
  }
  // The page's word bits: mostly none (a page of data; the scratchpad's "pages" past RAM's never
  // hold any), so the word's own bit is tested off the main path.
  Label& page_code = cold_label();
  if (const auto d = from_context(lay.code_bits);
      d && from_context(lay.code_bits + CodePages::kPages + CodePages::kSparePages)) {
    cmp(qword[rbx + rdx * 8 + *d], 0);
  } else {
    mov(rsi, reinterpret_cast<u64>(lay.code_bits));
    cmp(qword[rsi + rdx * 8], 0);
  }
  jne(page_code, T_NEAR);
  L(done);
  cold.push_back([this, &done, &page_code] {
    L(page_code);
    mov(rsi, reinterpret_cast<u64>(lay.code_bits));
    mov(rsi, qword[rsi + rdx * 8]);
    mov(edx, r13d);
    shr(edx, 2);
    bt(rsi, rdx);  // the word's bit (the offset counts modulo 64)
    jnc(done, T_NEAR);
    // A word holding compiled code: its page's blocks are dropped.
    mov(rdi, reinterpret_cast<u64>(lay.code_pages));
    mov(esi, r13d);
    call_leaf(reinterpret_cast<const void*>(lay.code_write));
    jmp(done, T_NEAR);
  });
}

// LWC2 past its checks: wait_load() (the GTE load is not shadowed but waits its turn), Bus::read32
// (RAM: kRamRead cycles; the scratchpad: none), wait_gte(), and the GTE register write.
void Impl::lwc2(u32 i) {
  Label read;
  mov(rcx, cpu64(lay.load_done_at));
  cmp(now, rcx);
  cmovb(now, rcx);
  test(r13d, kScratchOffset);
  jnz(read);
  add(now, lay.ram_read);
  L(read);
  mov(r8d, dword[host_at(r13, false)]);
  wait_gte();
  if (const auto f = Gte::data_field(cpu_detail::rt(i), true)) return gte_write(*f, r8d);
  mov(rdi, reinterpret_cast<u64>(lay.gte));
  mov(esi, cpu_detail::rt(i));
  mov(edx, r8d);
  call_leaf(reinterpret_cast<const void*>(lay.gte_write_data));
}

// MFHI/MFLO (eax, after wait_muldiv: time goes on to when a multiply or divide is done) and
// MTHI/MTLO.
void Impl::hilo(NativeOp op, u32 i) {
  const int field = op == NativeOp::Mfhi || op == NativeOp::Mthi ? lay.hi : lay.lo;
  if (op == NativeOp::Mthi || op == NativeOp::Mtlo) {
    read_eax(cpu_detail::rs(i));
    mov(cpu32(field), eax);
    return;
  }
  mov(rcx, cpu64(lay.muldiv_ready_at));
  cmp(now, rcx);
  cmovb(now, rcx);
  mov(eax, cpu32(field));
}

}  // namespace psx
