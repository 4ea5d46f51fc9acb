// The end of a compiled block (emitter_impl.h): RecompilerT::run()'s next loop pass made by the
// block itself, which jumps on to the next compiled block where the dispatcher would have nothing
// else to do, and the idle-loop head that such a jump may pass as the dispatcher would.
#include <utility>

#include "core/cpu/idle_skip.h"
#include "core/cpu/recompiler/emitter_impl.h"

namespace psx {

using Xbyak::Label;
using Impl = BlockEmitter::Impl;

// The block's end: RecompilerT::run()'s next loop pass. When it would call the block that
// find()'s table holds for the pc (no stop, time before the deadline, no idle-loop head to hand
// to IdleSkip but one backing off, loop_head_routine(), no written code pages whose blocks must
// be dropped first), the block jumps there itself, past that block's prologue (kPrologueBytes),
// in the same frame and with the time and count still in their registers; otherwise it writes
// them back and returns to the dispatcher, which makes the same checks and does what they ask. A
// `clean` chain, from a native run that reached the block's end on anything but a branch, also
// skips the next block's pc_checks() and state_checks() (kCleanEntry): the run leaves the former
// true, the latter held when it started, and of what they check only a hook could have changed
// since. It skips the next block's loop_head_check() too, having seen no loop head pending, or
// none that matters (no idle skipping), or the one at its pc cleared by loop_head_routine(); a
// loop head pending elsewhere (left by an exception before the branch's target was reached)
// sends it back to the dispatcher. Nor does it check the deadline itself (but after a deferred
// shadow check, shadow()): the clean entry does before anything changes (its budget check, or a
// deadline check where the first run has no budget, or the first call's may_step()), and at the
// deadline its refusal leaves by a call that answers false to the exit's chain, which does check
// (else it would enter the block again).
// A block that is one native segment and branches back to its start (loops_natively) goes, on that
// branch, straight to its first instruction (`loop`, the segment's resume[0]) past its whole guard
// when no call was made since the guard passed (the frame's spare byte at rsp says; a load or
// store made by a call may have written the cache control or raised an interrupt): a native pass
// through it changes nothing the guard checked but what this chain checks (the time, a stop, a
// hook, the loop head), and no i-cache line the block uses (a fill stub refills a line with the
// words compiled; stores leave the i-cache alone).
// Where the pc is known now (`target`, after a split branch's delay slot: split_end()), the
// chain compares and looks up that pc without reading pc_.
void Impl::chain(bool clean, Label* loop, std::optional<u32> loop_budget, std::optional<u32> target) {
  const bool native_end = clean;
  clean = clean && !ends_in_branch;  // a branch's delay slot is the next block's (pc_checks())
  const bool deferred = std::exchange(defer_shadow, false);
  Label back, no_loop_head, loop_head_pending;
  // stop_ and hook_armed_ together (Layout), and the written-code flag where it follows them.
  const bool flag_follows = from_context(lay.any_dirty) == lay.stop + 2;
  if (flag_follows) test(dword[rbx + lay.stop], clean ? 0x00FFFFFF : 0x00FF00FF);
  else if (clean) cmp(word[rbx + lay.stop], 0);
  else cmp(byte[rbx + lay.stop], 0);
  jne(back, T_NEAR);
  // A clean chain leaves the deadline to the next block's clean entry (above), except after a
  // deferred shadow check: a refusal there at the deadline would leave before the next
  // instruction's check, which is to make this one's.
  if (!clean || deferred) {
    cmp(now, deadline);
    jae(back, T_NEAR);
  }
  if (clean) {  // mostly no loop head is pending: then on, past the next block's loop-head check
    cmp(cpu32(lay.loop_head), lay.no_loop_head);
    jne(loop_head_pending, T_NEAR);
  } else {
    loop_head_at_pc(target, no_loop_head, back);
  }
  L(no_loop_head);
  if (!target) {
    mov(eax, cpu32(lay.pc));
    if (!(native_end && aligned_end)) {  // a misaligned pc (JR's) raises its address error outside
      test(al, 3);
      jnz(back, T_NEAR);
    }
  }
  if (!flag_follows) {
    if (const auto d = from_context(lay.any_dirty)) {
      cmp(byte[rbx + *d], 0);
    } else {
      mov(rcx, reinterpret_cast<u64>(lay.any_dirty));
      cmp(byte[rcx], 0);
    }
    jne(back, T_NEAR);
  }
  // This block is find()'s for its own pc while no code page is written.
  if (clean && self_loop && (!target || *target == block_pc)) {
    Label other;
    if (!target) {
      cmp(eax, block_pc);
      jne(other);
    }
    if (loop) {  // the segment's guard's deadline budget, then past the guard
      Label guarded;
      cmp(byte[rsp], 0);
      jne(guarded);
      if (loop_budget) budget_check(*loop_budget, guarded);
      jmp(*loop, T_NEAR);
      L(guarded);
    }
    jmp(block_entry + kCleanEntry, T_NEAR);
    L(other);
  }
  // Where the pc is known now, a link site: a jump to that pc's block once it is compiled
  // (block_links.h), until then to the lookup after it. Else, and until then, the recent table's
  // entry for the pc (pc / 4 mod recent_count), of 16 bytes: {u32 pc; BlockFn fn at 8}.
  if (target) {
    db(0xE9);  // jmp rel32
    links.push_back({const_cast<u8*>(getCurr()), *target, u32(clean ? kCleanEntry : kPrologueBytes)});
    dd(0);
    const auto* cell = static_cast<const char*>(lay.recent_blocks) + ((*target >> 2) & (lay.recent_count - 1)) * 16;
    const auto d = from_context(cell + 8);  // the entry's both ends within reach of rbx
    if (d && from_context(cell)) {
      cmp(dword[rbx + *d - 8], *target);
      jne(back, T_NEAR);
      mov(rax, qword[rbx + *d]);
    } else {
      mov(rdx, reinterpret_cast<u64>(cell));
      cmp(dword[rdx], *target);
      jne(back, T_NEAR);
      mov(rax, qword[rdx + 8]);
    }
  } else {
    mov(ecx, eax);
    and_(ecx, (lay.recent_count - 1) << 2);
    shl(ecx, 2);
    const auto* table = static_cast<const char*>(lay.recent_blocks);
    const auto d = from_context(table);
    if (d && from_context(table + lay.recent_count * 16)) {  // the whole table within reach of rbx
      cmp(dword[rbx + rcx + *d], eax);
      jne(back, T_NEAR);
      mov(rax, qword[rbx + rcx + *d + 8]);
    } else {
      mov(rdx, reinterpret_cast<u64>(table));
      cmp(dword[rdx + rcx], eax);
      jne(back, T_NEAR);
      mov(rax, qword[rdx + rcx + 8]);
    }
  }
  add(rax, clean ? kCleanEntry : kPrologueBytes);
  jmp(rax);
  if (clean) {  // a loop head pending: without idle skipping none matters; else at the pc only
    L(loop_head_pending);
    cmp(now, deadline);  // at the deadline, the loop head stays for the dispatcher
    jae(back, T_NEAR);
    cmp(qword[rbx + lay.idle_skip], 0);
    je(no_loop_head, T_NEAR);
    loop_head_at_pc(target, no_loop_head, back);  // the routine cleared it where it goes on
    jmp(back, T_NEAR);  // elsewhere (rare: an exception before the branch's target was reached)
  }
  L(back);
  if (deferred) {  // the last instruction's shadow check (shadow()), at its time
    Label keep;
    cmp(cpu32(lay.shadow_reg), 0);
    je(keep);
    cmp(now, cpu64(lay.load_done_at));
    jb(keep);
    mov(cpu32(lay.shadow_reg), 0);
    L(keep);
  }
  flush();
  epilogue();
  ret();
}

// Where chain()'s pc (`target`, else pc_) is the loop head: to `go_on` where loop_head_routine()
// lets the chain go on, else to `back`. Elsewhere on past this code.
void Impl::loop_head_at_pc(std::optional<u32> target, Label& go_on, Label& back) {
  Label differ;
  if (target) {
    cmp(cpu32(lay.loop_head), *target);
    jne(differ);
    mov(eax, *target);
  } else {
    mov(eax, cpu32(lay.pc));
    cmp(eax, cpu32(lay.loop_head));
    jne(differ);
  }
  call(loop_head_routine());
  jz(go_on, T_NEAR);
  jmp(back, T_NEAR);
  L(differ);
}

// chain()'s pc (in eax) is the loop head: run() would hand it to IdleSkip::at_loop_head(), whose
// most common answer, for a loop that failed to qualify and is backing off, is to count one visit
// off and let the loop run on. This routine (one per block, with the cold code) gives that answer
// itself, clearing the loop head as run() does, and leaves every other case to the dispatcher:
// ZF set when the chain may go on (also without idle skipping), clear when it must go back. A tight
// loop that stores (a memset, a sieve) would otherwise return to the dispatcher every iteration.
Label& Impl::loop_head_routine() {
  if (!loop_head_entry) {
    loop_head_entry = &cold_label();
    cold.push_back([this, &entry = *loop_head_entry] {
      Label refuse, done;
      L(entry);
      mov(rdx, cpu64(lay.idle_skip));
      test(rdx, rdx);
      jz(done);  // ZF set
      cmp(eax, dword[rdx + lay.idle_last_head]);  // right after a skip: at_loop_head() decides
      je(refuse);
      mov(ecx, eax);
      shr(ecx, 2);
      and_(ecx, IdleSkip::kBackoffEntries - 1);
      imul(ecx, ecx, IdleSkip::kBackoffBytes);
      add(rdx, rcx);
      cmp(dword[rdx + lay.idle_backoff], eax);  // the entry's head
      jne(refuse);
      const Xbyak::Address visits = dword[rdx + lay.idle_backoff + IdleSkip::kBackoffVisits];
      cmp(visits, 0);  // left before the next examination
      je(refuse);
      sub(visits, 1);
      mov(cpu32(lay.loop_head), lay.no_loop_head);
      cmp(eax, eax);  // ZF set
      L(done);
      ret();
      L(refuse);
      test(rdx, rdx);  // ZF clear (rdx is the IdleSkip or past it)
      ret();
    });
  }
  return *loop_head_entry;
}

}  // namespace psx
