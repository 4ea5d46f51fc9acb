// Time in compiled blocks (emitter_impl.h): the deadline's budget, which lets a native run check
// the deadline once instead of before each instruction, the cycles a run owes its time register
// (Impl::owed), and the load shadow's check and wait (CpuT::shadow_stall(), the load-timing model
// at CpuT::kLoadIssue).
#include <algorithm>

#include "core/cpu/decode.h"
#include "core/cpu/recompiler/emitter_impl.h"

namespace psx {

using Xbyak::Label;
using Impl = BlockEmitter::Impl;

// The most cycles instruction j of a native run can add to the time and to when the loads,
// multiplies and divides and GTE commands in flight end (its own cycle, a load's issue and bus
// access, LWC2's read, a command's or a multiply's or divide's duration, and the fill of a line
// it is the first of the run to reach), once it has waited for those in flight (longest_wait()).
u32 Impl::most_cycles(std::span<const Step> run, size_t j) const {
  using namespace cpu_detail;
  const Step& s = run[j];
  const NativeOp op = s.native;
  u32 cycles = 1;
  if ((j == 0 || (s.pc & 15) == 0) && fills_natively(s.pc)) cycles += 4 * lay.fetch_word_cycles;
  if (is_load(op)) cycles += u32(lay.load_issue + lay.load_bus);
  else if (op == NativeOp::Lwc2) cycles += u32(lay.ram_read);
  else if (op == NativeOp::Gte) cycles += lay.gte_cycles(s.word & 0x1FFFFFF);
  else if (op == NativeOp::Mult || op == NativeOp::Multu) cycles += kMultiplySlowCycles;
  else if (op == NativeOp::Div || op == NativeOp::Divu) cycles += kDivideCycles;
  return cycles;
}

// How far past the time instruction s's wait for work already under way can reach: a load's
// access ends at most load_bus + 1 cycles after the load (CpuT::timed_read(); every instruction
// may wait for it, through the shadow or a fill), a GTE command (which s waits for if it is a
// GTE instruction) at most gte_longest after it starts, a multiply or divide (MFHI/MFLO) at most
// kDivideCycles; time only grows, so each stays within that of the time.
u32 Impl::longest_wait(const Step& s) const {
  const u32 load = u32(lay.load_bus + 1);
  if (is_cop2(s.native)) return std::max(load, lay.gte_longest);
  if (s.native == NativeOp::Mfhi || s.native == NativeOp::Mflo) return std::max(load, cpu_detail::kDivideCycles);
  return load;
}

// The deadline checks before instructions k + 1 .. count - 1 of a segment (and before k itself
// where it resumes after a call), made once before instruction k (and its line's fill): when the
// time plus `budget` (Segment::budget[k]) is before the deadline, every one of them would pass,
// so native code runs on without them; otherwise the instructions run as their calls (`fail`),
// which check the deadline one by one. Each of those instructions adds at most most_cycles() to
// the time, after a first wait of at most the longest of their longest_wait(). Leaves rax changed.
void Impl::budget_check(u32 budget, Label& fail) {
  if (budget == 0) {
    cmp(now, deadline);
  } else {
    lea(rax, ptr[now + int(budget)]);
    cmp(rax, deadline);
  }
  jae(fail, T_NEAR);
}

// Impl::owed: r14 catches up with the time.
void Impl::settle() {
  if (owed == 1) inc(now);
  else if (owed > 1) add(now, int(owed));
  owed = 0;
}

// The instructions whose native code reads or moves the time: loads and LWC2 (the load-timing
// model, wait_load()), SWC2 and the GTE's (wait_gte()), MFHI/MFLO (the multiply's or divide's
// end), multiplies and divides (their duration).
bool Impl::uses_time(NativeOp op) {
  return is_load(op) || is_cop2(op) || op == NativeOp::Mfhi || op == NativeOp::Mflo ||
         (op >= NativeOp::Mult && op <= NativeOp::Divu);
}

// The registers instruction s reads that a load may shadow (none but r0 is never shadowed).
std::vector<u32> Impl::shadowable_reads(const Step& s) {
  using namespace cpu_detail;
  std::vector<u32> regs;
  for (u32 r : {rs(s.word), rt(s.word)})
    if (r != 0 && reads_reg(s.word, r) && (regs.empty() || regs[0] != r)) regs.push_back(r);
  return regs;
}

// Whether instruction s, which a load to r (not r0) shadows, waits for that load's access: it
// reads r, and not in a load delay slot of r (`delay_slot`), where it reads the old value.
// shadow_known() emits the wait, and plan_shadow() knows the shadow clear after it.
bool Impl::waits_for_load(const Step& s, u32 r, bool delay_slot) {
  const std::vector<u32> reads = shadowable_reads(s);
  return r != 0 && !delay_slot && std::find(reads.begin(), reads.end(), r) != reads.end();
}

// CpuT::shadow_stall() where shadow_reg_ is nonzero, in the cold code up to the wait: the
// shadow clears once the access has ended, and only an instruction reading the shadowed register
// may wait (`stall`: stall_stub(), with ecx = the register). Goes on inline where nothing waits;
// the main path only tests shadow_reg_, which is mostly zero by the time a run starts.
void Impl::shadow_check(const Step& s, Label& stall) {
  Label &pending = cold_label(), &back = cold_label();
  cmp(cpu32(lay.shadow_reg), 0);  // eax may hold a register (eax_reg)
  jne(pending, T_NEAR);
  L(back);
  cold.push_back([this, &pending, &back, &stall, reads = shadowable_reads(s), at = owed] {
    Label clear;
    L(pending);
    mov(ecx, cpu32(lay.shadow_reg));
    lea(rdx, ptr[now + int(at)]);  // the time (Impl::owed); eax may hold a register
    cmp(rdx, cpu64(lay.load_done_at));
    jae(clear);
    for (u32 r : reads) {
      cmp(ecx, r);
      je(stall, T_NEAR);
    }
    jmp(back, T_NEAR);
    L(clear);
    mov(cpu32(lay.shadow_reg), 0);
    jmp(back, T_NEAR);
  });
}

// Whether instruction s, k of the segment, may wait for a load no earlier instruction of the
// segment made: its check of the load shadow is dynamic and it reads a register a load may
// shadow, so it has a stall_stub().
bool Impl::has_stall(const Step& s, const Segment& seg, size_t k) {
  return has_stall(s, seg.shadow[k], seg.shadowed[k]);
}

bool Impl::has_stall(const Step& s, Shadow shadow, u32 shadowed) {
  return shadow == Shadow::check && shadowed == Segment::kUnknownShadow && !shadowable_reads(s).empty();
}

// Segment::shadow and Segment::shadowed for a segment's instructions; `reach`: instructions
// since the last that may have left a load shadowed, this one included (kLoadIssue + kLoadBus - 1).
// Instructions after one that waits for the segment's last load (shadow_known()) still check:
// that load's address may have gone through the bus interface, whose tail ends apart.
void Impl::plan_shadow(std::span<const Step> run, u32 reach, std::vector<Shadow>& shadow,
                       std::vector<u32>& shadowed) {
  shadow.resize(run.size());
  shadowed.assign(run.size(), Segment::kUnknownShadow);
  bool known = false;  // run[last] is a load whose shadow native code knows (not an I/O load)
  for (size_t k = 0, since = 1, last = 0; k < run.size(); ++k) {
    shadow[k] = since > reach ? Shadow::none : since < reach ? Shadow::check : Shadow::clear;
    if (shadow[k] == Shadow::check && known && k - last < reach) shadowed[k] = cpu_detail::rt(run[last].word);
    if (is_load(run[k].native)) {
      // An I/O load's bus tail ends where its call finds (CpuT::io_tail()), and its call for
      // another address (its fallback) may be a RAM load's: both checked at run time.
      known = run[k].io == 0;
      last = k;
    }
    since = is_load(run[k].native) ? 1 : since + 1;
  }
}

// CpuT::shadow_stall() before instruction k, as seg.shadow[k] and seg.shadowed[k] say.
// The check that only clears shadow_reg_ is left to the chain (defer_shadow) at the last
// instruction of a run that ends the block (Segment::ends_block, chain(true)) when that
// instruction does not read or move the time after its check: the chain's way back to the
// dispatcher makes it at the same time, and on its ways on the next instruction's own check
// clears as this one would have. That next instruction is the next block's, run natively or as
// a call that executes it: the chain has checked all that may_step() checks but a hook and
// interrupts; no native instruction raises an interrupt, and a hook armed by a branch ending the
// block is left alone in its delay slot, where the next block starts (CpuT::step()).
void Impl::shadow(const Step& s, size_t k, Segment& seg) {
  const bool last = k + 1 == seg.count || exit_way || s.io != 0;  // an I/O load's call sees it
  const bool deferred = last && (seg.ends_block || exit_way) && !uses_time(s.native);
  if (seg.shadow[k] == Shadow::check && seg.shadowed[k] != Segment::kUnknownShadow) {
    shadow_known(s, seg.pipe[k], seg.shadowed[k], last && !deferred);
    defer_shadow = deferred;
  } else if (seg.shadow[k] == Shadow::check) {
    // Where s reads no register a load may shadow, the check could only clear shadow_reg_, which
    // only the segment's last instruction must do (the reasoning of shadow_known(), which holds
    // for a shadow left by an earlier block just as for the segment's own load).
    const bool stalls = has_stall(s, seg, k);
    if (!stalls && (!last || deferred)) {
      defer_shadow = deferred;
      return;
    }
    seg.stall_owed[k] = owed;
    shadow_check(s, seg.stall[k]);
    if (stalls) L(seg.stall_back[k]);  // else no stall_stub() comes back
  } else if (seg.shadow[k] == Shadow::clear) {
    mov(cpu32(lay.shadow_reg), 0);
  }
}

// CpuT::shadow_stall() where a load of the segment, rt = r, is the last before instruction s
// and within reach. Every load waits for the access before it (timed_read(): wait_load(), or
// its own access starting after that one's end), so either the access in flight is that
// load's, with shadow_reg_ = r, or it has ended (now >= load_done_at_), and then the check
// clears shadow_reg_ whatever it holds; or the load's address, not the guessed one, went through
// the bus interface: by cached code its tail shadows r too (CpuT::io_tail()), by other code it
// leaves no shadow, so the wait tests shadow_reg_. Which one is decided at run time, but whether s waits
// is known now: when it reads r outside r's load delay slot. No stub and no register compare:
// a waiting instruction moves time to the access's end (no earlier than now) and clears.
// Where s does not wait, the check only clears shadow_reg_, and only the segment's `last`
// instruction makes it: nothing in the segment reads shadow_reg_ after its load (a later load
// sets it, a waiting instruction clears it whatever it holds), every way out before the last
// instruction runs that instruction's step, whose own check clears it just as the skipped ones
// would have (time only grows, so a check that would have cleared earlier clears there), and
// the last instruction's check leaves it as the instructions between would have.
void Impl::shadow_known(const Step& s, const Pipe& pipe, u32 r, bool last) {
  if (waits_for_load(s, r, pipe.after_load && pipe.load_reg == r)) {
    settle();
    Label clear;
    cmp(cpu32(lay.shadow_reg), 0);  // no shadow left (CpuT::io_tail() from uncached code)
    je(clear);
    mov(rcx, cpu64(lay.load_done_at));
    cmp(now, rcx);
    cmovb(now, rcx);
    L(clear);
    mov(cpu32(lay.shadow_reg), 0);
    return;
  }
  if (!last) return;
  settle();
  Label pending;
  cmp(now, cpu64(lay.load_done_at));
  jb(pending);
  mov(cpu32(lay.shadow_reg), 0);
  L(pending);
}

// The wait of CpuT::shadow_stall() for instruction k, which reads the register shadowed (ecx)
// before its load's access has ended, returning to its stall_back: none in the load's delay slot
// (load_reg_ is the shadowed register: the old value is read), else until the access ends.
void Impl::stall_stub(size_t k, Segment& seg) {
  const Pipe& pipe = seg.pipe[k];
  L(seg.stall[k]);
  if (pipe.dynamic) {
    cmp(ecx, cpu32(lay.load_reg));
    je(seg.stall_back[k], T_NEAR);
  } else if (pipe.after_load && pipe.load_reg != 0) {
    cmp(ecx, pipe.load_reg);
    je(seg.stall_back[k], T_NEAR);
  }
  mov(now, cpu64(lay.load_done_at));
  if (seg.stall_owed[k] != 0) sub(now, int(seg.stall_owed[k]));  // still owed after the stall
  mov(cpu32(lay.shadow_reg), 0);
  jmp(seg.stall_back[k], T_NEAR);
}

}  // namespace psx
