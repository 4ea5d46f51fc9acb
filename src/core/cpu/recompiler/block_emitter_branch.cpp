// Branches and jumps in compiled blocks (emitter_impl.h): CpuT::execute()'s branch() for native
// code, the hooks a jump arms, and the split end of a segment whose last two instructions are a
// branch to a target known now and a delay slot that cannot leave native code (Segment::split).
#include "core/cpu/decode.h"
#include "core/cpu/recompiler/emitter_impl.h"

namespace psx {

using Xbyak::Label;
using Impl = BlockEmitter::Impl;

// CpuT::arm_hook() for a target known now / in ecx.
void Impl::arm_hook_static(u32 target) {
  Label skip;
  const u32 p = target & 0x1FFFFFFF;
  if (p != 0xA0 && p != 0xB0 && p != 0xC0) {
    cmp(cpu32(lay.extra_hook_pc), target);
    jne(skip);
  }
  cmp(qword[rbx + lay.hooks], 0);
  je(skip);
  mov(byte[rbx + lay.hook_armed], 1);
  mov(cpu32(lay.hook_pc), target);
  L(skip);
}

// The main path tests only what rules a hook out for almost every target: a BIOS vector's
// address has no bits set but 4-7 and the segment's (29-31), and it is not extra_hook_pc_.
void Impl::arm_hook_ecx() {
  Label &maybe = cold_label(), &back = cold_label();
  test(ecx, 0x1FFFFF0F);
  jz(maybe, T_NEAR);
  cmp(ecx, cpu32(lay.extra_hook_pc));
  je(maybe, T_NEAR);
  L(back);
  cold.push_back([this, &maybe, &back] {
    Label arm;
    L(maybe);
    cmp(qword[rbx + lay.hooks], 0);
    je(back, T_NEAR);
    cmp(ecx, cpu32(lay.extra_hook_pc));
    je(arm);
    mov(edx, ecx);
    and_(edx, 0x1FFFFFFF);
    for (u32 v : {0xA0u, 0xB0u, 0xC0u}) {
      cmp(edx, v);
      je(arm);
    }
    jmp(back, T_NEAR);
    L(arm);
    mov(byte[rbx + lay.hook_armed], 1);
    mov(cpu32(lay.hook_pc), ecx);
    jmp(back, T_NEAR);
  });
}

// Where a branch or J/JAL at pc goes when taken (JR and JALR: nowhere known now).
u32 Impl::static_target(NativeOp op, u32 pc, u32 i) {
  if (op == NativeOp::J || op == NativeOp::Jal) return ((pc + 4) & 0xF0000000) | ((i & 0x03FFFFFF) << 2);
  return pc + 4 + (cpu_detail::simm(i) << 2);
}

// CpuT::execute() for a branch or jump at pc (not in a delay slot, so pc_ = pc + 4 and
// next_pc_ = pc + 8 now): branch() / loop_branch(), the link (eax) through write_reg, which
// the BcondZ links make whether or not the branch is taken, after reading rs.
// A split branch (Segment::split) only sets r8b to whether it is taken: split_end() makes the
// rest on each way.
void Impl::branch(NativeOp op, u32 pc, u32 i, bool split) {
  using namespace cpu_detail;
  Label not_taken;
  const u32 target = static_target(op, pc, i);
  const auto with_rs_zero = [&] { with_reg(rs(i), [&](const Xbyak::Operand& o) { cmp(o, 0); }); };
  const auto taken_if = [&](Cond c) {
    if (split) split_cond = c;
    else jump_if(negated(c), not_taken);
  };
  using enum Cond;
  switch (op) {
    case NativeOp::Beq: case NativeOp::Bne:  // compared from whichever eax holds
      if (in_eax(rt(i))) {
        with_reg(rs(i), [&](const Xbyak::Operand& o) { cmp(eax, o); });
      } else {
        read_eax(rs(i));
        cmp(eax, reg(rt(i)));
      }
      taken_if(op == NativeOp::Beq ? e : ne);
      break;
    case NativeOp::Blez: with_rs_zero(); taken_if(le); break;
    case NativeOp::Bgtz: with_rs_zero(); taken_if(g); break;
    case NativeOp::Bltz: with_rs_zero(); taken_if(l); break;
    case NativeOp::Bgez: with_rs_zero(); taken_if(ge); break;
    case NativeOp::Bltzal: with_rs_zero(); mov(eax, pc + 8); taken_if(l); break;  // mov keeps the flags
    case NativeOp::Bgezal: with_rs_zero(); mov(eax, pc + 8); taken_if(ge); break;
    case NativeOp::Jal: mov(eax, pc + 8); break;  // the link, written by the caller
    case NativeOp::Jr: case NativeOp::Jalr:
      with_reg(rs(i), [&](const Xbyak::Operand& o) { mov(ecx, o); });  // the target, read before the link is written
      if (op == NativeOp::Jalr) mov(eax, pc + 8);
      mov(cpu32(lay.next_pc), ecx);
      arm_hook_ecx();
      break;
    default: break;
  }
  if (split) return;
  if (op != NativeOp::Jr && op != NativeOp::Jalr) {
    mov(cpu32(lay.next_pc), target);
    taken(op, pc, target);
  }
  L(not_taken);
  mov(byte[rbx + lay.next_in_delay], 1);
}

Impl::Cond Impl::negated(Cond c) {
  using enum Cond;
  switch (c) {
    case e: return ne;
    case ne: return e;
    case l: return ge;
    case ge: return l;
    case le: return g;
    case g: break;
  }
  return le;
}

void Impl::jump_if(Cond c, Label& to) {
  switch (c) {
    case Cond::e: return je(to, T_NEAR);
    case Cond::ne: return jne(to, T_NEAR);
    case Cond::l: return jl(to, T_NEAR);
    case Cond::ge: return jge(to, T_NEAR);
    case Cond::le: return jle(to, T_NEAR);
    case Cond::g: return jg(to, T_NEAR);
  }
}

void Impl::keep_split_flags() {
  if (!split_cond) return;
  switch (*split_cond) {
    case Cond::e: sete(r8b); break;
    case Cond::ne: setne(r8b); break;
    case Cond::l: setl(r8b); break;
    case Cond::ge: setge(r8b); break;
    case Cond::le: setle(r8b); break;
    case Cond::g: setg(r8b); break;
  }
  split_cond.reset();
}

void Impl::unless_split_taken(Label& not_taken) {
  if (split_cond) {
    jump_if(negated(*split_cond), not_taken);
    split_cond.reset();
  } else {
    test(r8b, r8b);
    jz(not_taken, T_NEAR);
  }
}

// What a branch or J/JAL at pc does when taken to a target known now, besides next_pc_: CpuT's
// loop_branch() (all but JAL: a taken one a little backwards names a loop head) and arm_hook().
void Impl::taken(NativeOp op, u32 pc, u32 target) {
  if (op != NativeOp::Jal && target <= pc && pc - target < 256) mov(cpu32(lay.loop_head), target);
  arm_hook_static(target);
}

// Whether the block's last native segment splits at its branch (Segment::split): the segment
// ends in a branch or J/JAL, whose target is known now, and its delay slot (splits_at()).
bool Impl::splits(std::span<const Step> run, const Segment& seg) {
  return seg.count >= 2 && splits_at(run, seg.count - 2, seg.shadow, seg.shadowed);
}

// Whether instruction k of a segment, a branch or J/JAL whose target is known now, splits with
// its delay slot: an ALU operation that starts no i-cache line and waits for no load (no line
// check, no stall stub), so nothing between the branch and the delay slot's end leaves native
// code, and each way can run the delay slot knowing where it goes.
bool Impl::splits_at(std::span<const Step> run, size_t k, const std::vector<Shadow>& shadow,
                     const std::vector<u32>& shadowed) {
  const Step &b = run[k], &d = run[k + 1];
  if (!is_branch(b.native) || b.native == NativeOp::Jr || b.native == NativeOp::Jalr) return false;
  if (d.native < NativeOp::Addiu || d.native > NativeOp::Sltu || (d.pc & 15) == 0) return false;
  return !has_stall(d, shadow[k + 1], shadowed[k + 1]);
}

bool BlockEmitter::goes_on(std::span<const Step> steps, u32 shadow_reach) {
  if (steps.size() < 2) return false;
  const Step& branch = steps[steps.size() - 2];
  const NativeOp b = branch.native;
  const bool conditional = b >= NativeOp::Beq && b != NativeOp::J && b != NativeOp::Jal && b != NativeOp::Jr &&
                           b != NativeOp::Jalr;
  // Never past one taken whatever the registers hold: GCC's `b` (BEQ r0, r0) and `bal` (BGEZAL r0),
  // often the last word of a function, before data that the block would take for code (and be
  // dropped by every store to it).
  const u32 s = cpu_detail::rs(branch.word), t = cpu_detail::rt(branch.word);
  const bool always = (b == NativeOp::Beq && s == t) ||
                      (s == 0 && (b == NativeOp::Blez || b == NativeOp::Bgez || b == NativeOp::Bgezal));
  if (!conditional || always) return false;
  size_t first = steps.size() - 2;  // the native segment holding the branch starts there
  while (first > 0 && steps[first - 1].native != NativeOp::None) --first;
  const std::span<const Step> run = steps.subspan(first);
  std::vector<Shadow> shadow;
  std::vector<u32> shadowed;
  Impl::plan_shadow(run, shadow_reach, shadow, shadowed);
  return Impl::splits_at(run, run.size() - 2, shadow, shadowed);
}

// A split segment's end: the branch has set r8b when taken (branch()), or is J/JAL. Each way
// makes what the branch does when taken (taken()) or not, runs the delay slot with pc_ and
// next_pc_ known (delay_dest) and chains to its destination. Neither way writes next_in_delay_:
// the branch left it zero, as it was before the branch, and the delay slot would have zeroed it.
void Impl::split_end(std::span<const Step> run, Segment& seg, std::optional<u32> budget) {
  const Step& b = run[seg.count - 2];
  const u32 target = static_target(b.native, b.pc, b.word);
  const u32 owed_then = owed, eax_then = eax_reg;
  const auto way = [&](u32 dest) {
    owed = owed_then;
    eax_reg = eax_then;
    delay_dest = dest;
    native(run.subspan(seg.count - 1), seg.count - 1, true, seg);
    delay_dest.reset();
    settle();
    add(instructions, int(seg.count));
    chain(true, loops_natively ? &seg.resume[0] : nullptr, budget, dest);
  };
  Label not_taken;
  const bool always = b.native == NativeOp::J || b.native == NativeOp::Jal;
  if (!always) unless_split_taken(not_taken);
  taken(b.native, b.pc, target);
  way(target);
  if (always) return;
  L(not_taken);
  way(b.pc + 8);
}

// A conditional branch split inside the block (Segment::mid), instruction k of the segment: it
// has set r8b when taken (branch()). The taken way makes what the branch does when taken, runs
// the delay slot knowing where it goes and chains to the target, as split_end() does; the other
// runs the delay slot and goes on with the segment at k + 2, whose instructions then see the
// pipeline, the time owed and eax as on a straight run.
void Impl::split_mid(std::span<const Step> run, Segment& seg, size_t k, std::optional<u32> budget) {
  const Step& b = run[k];
  const u32 target = static_target(b.native, b.pc, b.word);
  const u32 owed_then = owed, eax_then = eax_reg;
  Label not_taken;
  unless_split_taken(not_taken);
  taken(b.native, b.pc, target);
  delay_dest = target;
  exit_way = true;
  native(run.subspan(k + 1), k + 1, true, seg);
  exit_way = false;
  settle();
  add(instructions, int(k + 2));
  chain(true, loops_natively ? &seg.resume[0] : nullptr, budget, target);
  L(not_taken);
  owed = owed_then;
  eax_reg = eax_then;
  delay_dest = b.pc + 8;
  quiet_delay = true;
  native(run.subspan(k + 1), k + 1, true, seg);
  quiet_delay = false;
  delay_dest.reset();
}

}  // namespace psx
