// Emits compiled blocks (block_emitter.h) with xbyak (System V x86-64 calling convention).
// Registers while a block runs: rbx = the context (the CPU), r12 = the scheduler.
#include "core/cpu/recompiler/block_emitter.h"

#include <xbyak/xbyak.h>

#include <vector>

#include "core/cpu/cop0.h"
#include "core/cpu/decode.h"

namespace psx {

namespace {

using Xbyak::Label;
using Xbyak::Reg64;

// One native segment's pieces emitted after the block's main path: the slow path (its steps as
// calls) and the shadow-stall stubs.
struct Segment {
  size_t first, count;
  Label guard_failed, end;
  std::vector<Label> stall, stall_back;
};

}  // namespace

struct BlockEmitter::Impl : Xbyak::CodeGenerator {
  explicit Impl(size_t bytes) : Xbyak::CodeGenerator(bytes), capacity(bytes) {}
  const size_t capacity;
  Layout lay{};
  Label* exit = nullptr;  // the block's epilogue

  Xbyak::Address reg(u32 r) { return dword[rbx + lay.regs + 4 * int(r)]; }
  Xbyak::Address cpu32(int off) { return dword[rbx + off]; }

  void call_step(const Step& s) {
    mov(rdi, rbx);
    mov(esi, s.pc);
    mov(edx, s.word);
    mov(rax, reinterpret_cast<u64>(s.fn));
    call(rax);
    test(al, al);
    jz(*exit, T_NEAR);
  }

  // eax = the instruction's result (CpuT::execute's value for write_reg).
  void alu(NativeOp op, u32 i) {
    using namespace cpu_detail;
    switch (op) {
      case NativeOp::Addiu: mov(eax, reg(rs(i))); add(eax, simm(i)); break;
      case NativeOp::Slti: xor_(eax, eax); cmp(reg(rs(i)), simm(i)); setl(al); break;
      case NativeOp::Sltiu: xor_(eax, eax); cmp(reg(rs(i)), simm(i)); setb(al); break;
      case NativeOp::Andi: mov(eax, reg(rs(i))); and_(eax, imm(i)); break;
      case NativeOp::Ori: mov(eax, reg(rs(i))); or_(eax, imm(i)); break;
      case NativeOp::Xori: mov(eax, reg(rs(i))); xor_(eax, imm(i)); break;
      case NativeOp::Lui: mov(eax, imm(i) << 16); break;
      case NativeOp::Sll: mov(eax, reg(rt(i))); shl(eax, u8(shamt(i))); break;
      case NativeOp::Srl: mov(eax, reg(rt(i))); shr(eax, u8(shamt(i))); break;
      case NativeOp::Sra: mov(eax, reg(rt(i))); sar(eax, u8(shamt(i))); break;
      // x86 masks a shift count to 5 bits, as MIPS does (s & 31).
      case NativeOp::Sllv: mov(eax, reg(rt(i))); mov(ecx, reg(rs(i))); shl(eax, cl); break;
      case NativeOp::Srlv: mov(eax, reg(rt(i))); mov(ecx, reg(rs(i))); shr(eax, cl); break;
      case NativeOp::Srav: mov(eax, reg(rt(i))); mov(ecx, reg(rs(i))); sar(eax, cl); break;
      case NativeOp::Addu: mov(eax, reg(rs(i))); add(eax, reg(rt(i))); break;
      case NativeOp::Subu: mov(eax, reg(rs(i))); sub(eax, reg(rt(i))); break;
      case NativeOp::And: mov(eax, reg(rs(i))); and_(eax, reg(rt(i))); break;
      case NativeOp::Or: mov(eax, reg(rs(i))); or_(eax, reg(rt(i))); break;
      case NativeOp::Xor: mov(eax, reg(rs(i))); xor_(eax, reg(rt(i))); break;
      case NativeOp::Nor: mov(eax, reg(rs(i))); or_(eax, reg(rt(i))); not_(eax); break;
      case NativeOp::Slt: mov(ecx, reg(rs(i))); xor_(eax, eax); cmp(ecx, reg(rt(i))); setl(al); break;
      case NativeOp::Sltu: mov(ecx, reg(rs(i))); xor_(eax, eax); cmp(ecx, reg(rt(i))); setb(al); break;
      default: break;
    }
  }

  static bool is_branch(NativeOp op) { return op >= NativeOp::Beq; }

  // The register the instruction writes through write_reg (0: none).
  static u32 dest(NativeOp op, u32 i) {
    if (op == NativeOp::Jal) return 31;
    if (op == NativeOp::Jalr) return cpu_detail::rd(i);
    if (is_branch(op)) return 0;
    return op >= NativeOp::Sll ? cpu_detail::rd(i) : cpu_detail::rt(i);
  }

  // CpuT::arm_hook() for a target known now / in ecx.
  void arm_hook_static(u32 target) {
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
  void arm_hook_ecx() {
    Label skip, arm;
    cmp(qword[rbx + lay.hooks], 0);
    je(skip, T_NEAR);
    mov(edx, ecx);
    and_(edx, 0x1FFFFFFF);
    for (u32 v : {0xA0u, 0xB0u, 0xC0u}) {
      cmp(edx, v);
      je(arm);
    }
    cmp(ecx, cpu32(lay.extra_hook_pc));
    jne(skip);
    L(arm);
    mov(byte[rbx + lay.hook_armed], 1);
    mov(cpu32(lay.hook_pc), ecx);
    L(skip);
  }

  // CpuT::execute() for a branch or jump at pc (not in a delay slot, so pc_ = pc + 4 and
  // next_pc_ = pc + 8 now): branch() / loop_branch(), the link through write_reg.
  void branch(NativeOp op, u32 pc, u32 i) {
    using namespace cpu_detail;
    Label not_taken;
    const u32 target = op == NativeOp::J || op == NativeOp::Jal ? ((pc + 4) & 0xF0000000) | ((i & 0x03FFFFFF) << 2)
                                                                 : pc + 4 + (simm(i) << 2);
    switch (op) {
      case NativeOp::Beq: mov(eax, reg(rs(i))); cmp(eax, reg(rt(i))); jne(not_taken, T_NEAR); break;
      case NativeOp::Bne: mov(eax, reg(rs(i))); cmp(eax, reg(rt(i))); je(not_taken, T_NEAR); break;
      case NativeOp::Blez: cmp(reg(rs(i)), 0); jg(not_taken, T_NEAR); break;
      case NativeOp::Bgtz: cmp(reg(rs(i)), 0); jle(not_taken, T_NEAR); break;
      case NativeOp::Jal: mov(eax, pc + 8); break;  // the link, written by the caller
      case NativeOp::Jr: case NativeOp::Jalr:
        mov(ecx, reg(rs(i)));  // the target, read before the link is written
        mov(eax, pc + 8);
        mov(cpu32(lay.next_pc), ecx);
        arm_hook_ecx();
        break;
      default: break;
    }
    if (op != NativeOp::Jr && op != NativeOp::Jalr) {
      mov(cpu32(lay.next_pc), target);
      // loop_branch(): BEQ..BGTZ and J; a taken one a little backwards names a loop head.
      if (op != NativeOp::Jal && target <= pc && pc - target < 256) mov(cpu32(lay.loop_head), target);
      arm_hook_static(target);
    }
    L(not_taken);
    mov(byte[rbx + lay.next_in_delay], 1);
  }

  // Whether the segment may run as native code (else to its slow path): checked once for the whole
  // run because its instructions change none of it. They write only general registers, the pc,
  // the pipeline and time, so stop_, hooks, interrupts (SR, Cause, I_STAT, I_MASK), the loop
  // head, DCIC and the i-cache stay as they are; only the deadline, which time reaches, is checked
  // again before each instruction. Every word must be a fetch without time or fill (an i-cache
  // hit on a line held whole, Bus::fetch_hit) that is still the word compiled, checked once per
  // line for the line and once per word for the word.
  void guard(std::span<const Step> steps, Segment& seg) {
    Label& fail = seg.guard_failed;
    const u32 first = steps[seg.first].pc, bytes = u32(seg.count) * 4;
    cmp(byte[rbx + lay.stop], 0);
    jne(fail, T_NEAR);
    cmp(byte[rbx + lay.hook_armed], 0);
    jne(fail, T_NEAR);
    mov(rax, qword[r12 + lay.now]);
    cmp(rax, qword[r12 + lay.deadline]);
    jae(fail, T_NEAR);
    mov(eax, cpu32(lay.new_load_reg));
    or_(eax, cpu32(lay.new_load_val));
    jnz(fail, T_NEAR);
    test(cpu32(lay.dcic), Cop0::kDcicPCE);
    jnz(fail, T_NEAR);
    if (is_branch(steps[seg.first].native)) {  // branch() assumes it is not in a delay slot
      cmp(byte[rbx + lay.next_in_delay], 0);
      jne(fail, T_NEAR);
      cmp(cpu32(lay.next_pc), first + 4);
      jne(fail, T_NEAR);
    }
    Label no_loop_head, interrupts_off, no_irq;
    mov(eax, cpu32(lay.loop_head));  // run() would hand a loop head in the segment to IdleSkip
    sub(eax, first);
    cmp(eax, bytes);
    jae(no_loop_head);
    cmp(qword[rbx + lay.idle_skip], 0);
    jne(fail, T_NEAR);
    L(no_loop_head);
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
    for (size_t k = 0; k < seg.count; ++k) {
      const u32 pc = steps[seg.first + k].pc;
      if (k == 0 || (pc & 15) == 0) {
        mov(rax, reinterpret_cast<u64>(&lay.hot_lines[(pc >> 4) & 255]));
        cmp(dword[rax], pc & ~15u);
        jne(fail, T_NEAR);
        mov(rax, reinterpret_cast<u64>(&lay.icache_words[(pc >> 2) & 1020]));
      }
      cmp(dword[rax + 4 * ((pc >> 2) & 3)], steps[seg.first + k].word);
      jne(fail, T_NEAR);
    }
  }

  // Instruction k of a native segment: CpuT::run()'s loop pass and execute_at_pc(). The guard
  // has checked what no instruction of the segment can change (stop, hooks, interrupts, loop
  // heads, debug breaks, i-cache hits, new_load_* zero), so only time needs a check before each
  // instruction after the first. A branch may arm a hook or name a loop head, but only its delay
  // slot follows it in the segment, and step() leaves an armed hook alone in a delay slot, and
  // the loop head lies at or before the branch. After the first instruction the pipeline is
  // known: no load pending (new_load_* were zero), not in a delay slot, next_pc = pc + 4.
  // A branch's delay slot (after_branch) runs with in_delay_slot_ set and goes wherever the
  // branch set next_pc_.
  void native(const Step& s, size_t k, bool last_in_block, bool after_branch, Segment& seg) {
    if (k > 0) {
      mov(rax, qword[r12 + lay.now]);
      cmp(rax, qword[r12 + lay.deadline]);
      jae(*exit, T_NEAR);
    }
    mov(cpu32(lay.current_pc), s.pc);
    if (k == 0) {
      mov(al, byte[rbx + lay.next_in_delay]);
      mov(byte[rbx + lay.in_delay_slot], al);
      mov(byte[rbx + lay.next_in_delay], 0);
    } else if (after_branch) {
      mov(byte[rbx + lay.in_delay_slot], 1);
      mov(byte[rbx + lay.next_in_delay], 0);
    } else if (k == 1) {
      mov(byte[rbx + lay.in_delay_slot], 0);
    }
    inc(qword[rbx + lay.instructions]);
    inc(qword[r12 + lay.now]);
    seg.stall.emplace_back();
    seg.stall_back.emplace_back();
    cmp(cpu32(lay.shadow_reg), 0);
    jne(seg.stall.back(), T_NEAR);
    L(seg.stall_back.back());
    if (k == 0 || after_branch) {
      mov(eax, cpu32(lay.next_pc));
      mov(cpu32(lay.pc), eax);
      add(eax, 4);
      mov(cpu32(lay.next_pc), eax);
    } else {
      mov(cpu32(lay.pc), s.pc + 4);
      mov(cpu32(lay.next_pc), s.pc + 8);
    }
    if (is_branch(s.native)) branch(s.native, s.pc, s.word);
    else alu(s.native, s.word);
    const u32 d = dest(s.native, s.word);
    if (d != 0) mov(reg(d), eax);
    if (k > 0) return;  // load_reg_ = 0, load_val_ = 0: the commit writes r0 = 0 only
    // write_reg's `if (load_reg_ == d) load_reg_ = 0`, then the load delay slot's commit.
    Label skip;
    mov(ecx, cpu32(lay.load_reg));
    if (d != 0) {
      cmp(ecx, d);
      je(skip);
    }
    mov(edx, cpu32(lay.load_val));
    mov(dword[rbx + rcx * 4 + lay.regs], edx);
    L(skip);
    mov(reg(0), 0);
    mov(cpu32(lay.load_reg), 0);
    mov(cpu32(lay.load_val), 0);
    if (!last_in_block) {
      cmp(cpu32(lay.pc), s.pc + 4);
      jne(*exit, T_NEAR);
    }
  }

  // CpuT::shadow_stall() for instruction k (shadow_reg_ is nonzero), returning to its stall_back.
  void stall_stub(const Step& s, size_t k, Segment& seg) {
    using namespace cpu_detail;
    L(seg.stall[k]);
    Label stall;
    mov(rax, qword[r12 + lay.now]);
    cmp(rax, qword[rbx + lay.load_done_at]);
    jb(stall);  // not yet done: maybe wait
    mov(cpu32(lay.shadow_reg), 0);
    jmp(seg.stall_back[k], T_NEAR);
    L(stall);
    {
      Label wait;
      mov(eax, cpu32(lay.shadow_reg));
      if (k == 0) {  // in the load's delay slot the old value is read without waiting
        cmp(eax, cpu32(lay.load_reg));
        je(seg.stall_back[k], T_NEAR);
      }
      bool any = false;
      for (u32 r : {rs(s.word), rt(s.word)}) {
        if (r == 0 || !reads_reg(s.word, r)) continue;
        cmp(eax, r);
        je(wait);
        any = true;
      }
      jmp(seg.stall_back[k], T_NEAR);
      if (any) {
        L(wait);
        mov(rax, qword[rbx + lay.load_done_at]);
        mov(qword[r12 + lay.now], rax);
        mov(cpu32(lay.shadow_reg), 0);
        jmp(seg.stall_back[k], T_NEAR);
      } else {
        L(wait);  // unreferenced
      }
    }
  }
};

BlockEmitter::BlockEmitter(size_t buffer_bytes) : impl_(std::make_unique<Impl>(buffer_bytes)) {}
BlockEmitter::~BlockEmitter() = default;

BlockEmitter::BlockFn BlockEmitter::emit(const Layout& layout, std::span<const Step> steps) {
  // Upper bounds on one step's code (guard, inline, stall stub, slow call) and on the frame's.
  constexpr size_t kStepBytes = 384, kFrameBytes = 256;
  Impl& g = *impl_;
  if (g.getSize() + kFrameBytes + kStepBytes * steps.size() > g.capacity) return nullptr;
  g.lay = layout;
  Label done;
  g.exit = &done;
  g.align(16);
  const auto entry = g.getCurr<BlockFn>();
  // Three callee-saved pushes leave the stack 16-byte aligned at each call, as the ABI wants.
  g.push(g.rbx);
  g.push(g.r12);
  g.push(g.r13);
  g.mov(g.rbx, reinterpret_cast<u64>(layout.context));
  g.mov(g.r12, reinterpret_cast<u64>(layout.sched));
  std::vector<Segment> segments;
  segments.reserve(steps.size());
  for (size_t i = 0; i < steps.size();) {
    if (steps[i].native == NativeOp::None) {
      g.call_step(steps[i++]);
      continue;
    }
    Segment& seg = segments.emplace_back();
    seg.first = i;
    while (i < steps.size() && steps[i].native != NativeOp::None) ++i;
    seg.count = i - seg.first;
    seg.stall.reserve(seg.count);  // labels must not move once used
    seg.stall_back.reserve(seg.count);
    g.guard(steps, seg);
    for (size_t k = 0; k < seg.count; ++k) {
      const bool after_branch = k > 0 && Impl::is_branch(steps[seg.first + k - 1].native);
      g.native(steps[seg.first + k], k, seg.first + k + 1 == steps.size(), after_branch, seg);
    }
    g.L(seg.end);
  }
  g.L(done);
  g.pop(g.r13);
  g.pop(g.r12);
  g.pop(g.rbx);
  g.ret();
  for (Segment& seg : segments) {
    g.L(seg.guard_failed);
    for (size_t k = 0; k < seg.count; ++k) g.call_step(steps[seg.first + k]);
    g.jmp(seg.end, Xbyak::CodeGenerator::T_NEAR);
    for (size_t k = 0; k < seg.count; ++k) g.stall_stub(steps[seg.first + k], k, seg);
  }
  return entry;
}

void BlockEmitter::clear() { impl_->reset(); }

size_t BlockEmitter::bytes_used() const { return impl_->getSize(); }

}  // namespace psx
