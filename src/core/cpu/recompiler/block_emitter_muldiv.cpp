// Native MULT, MULTU, DIV and DIVU for compiled blocks (emitter_impl.h): CpuT::execute_special()'s
// results in HI/LO, including the documented division by zero and 0x80000000 / -1 results that
// x86's IDIV/DIV would fault on, and its timing model: the result is ready (for MFHI/MFLO's
// wait_muldiv) as cpu_detail's multiply/divide timing says (decode.h).
#include "core/cpu/decode.h"
#include "core/cpu/recompiler/emitter_impl.h"

namespace psx {

using Xbyak::Label;
using Impl = BlockEmitter::Impl;

namespace {

// r8 = a multiply's cycles for the magnitude in edx (cpu_detail::multiply_cycles).
void multiply_cycles(Impl& g) {
  using namespace cpu_detail;
  g.mov(g.r8d, kMultiplySlowCycles);
  g.mov(g.r9d, kMultiplyMediumCycles);
  g.cmp(g.edx, kMultiplyMediumBelow);
  g.cmovb(g.r8d, g.r9d);
  g.mov(g.r9d, kMultiplyFastCycles);
  g.cmp(g.edx, kMultiplyFastBelow);
  g.cmovb(g.r8d, g.r9d);
}

}  // namespace

void Impl::muldiv(NativeOp op, u32 i) {
  const u32 s = cpu_detail::rs(i), t = cpu_detail::rt(i);
  read_pair(s, t);
  if (op == NativeOp::Mult || op == NativeOp::Multu) {
    mov(edx, eax);
    if (op == NativeOp::Mult) {  // m = s < 0 ? ~s : s
      sar(edx, 31);
      xor_(edx, eax);
    }
    multiply_cycles(*this);
    if (op == NativeOp::Mult) imul(ecx);  // edx:eax = the 64-bit product
    else mul(ecx);
    mov(cpu32(lay.hi), edx);
    mov(cpu32(lay.lo), eax);
    lea(rax, ptr[now + r8]);
    mov(cpu64(lay.muldiv_ready_at), rax);
    return;
  }
  Label by_zero, divide, done;
  test(ecx, ecx);
  jz(by_zero);
  if (op == NativeOp::Div) {  // 0x80000000 / -1: HI = 0, LO = 0x80000000 (IDIV would trap)
    cmp(eax, 0x80000000);
    jne(divide);
    cmp(ecx, 0xFFFFFFFF);
    jne(divide);
    mov(cpu32(lay.hi), 0);
    mov(cpu32(lay.lo), 0x80000000);
    jmp(done);
  }
  L(divide);
  if (op == NativeOp::Div) {
    cdq();
    idiv(ecx);
  } else {
    xor_(edx, edx);
    div(ecx);
  }
  mov(cpu32(lay.hi), edx);
  mov(cpu32(lay.lo), eax);
  jmp(done);
  L(by_zero);  // HI = rs; LO = -1, or for DIV of a negative rs, 1
  mov(cpu32(lay.hi), eax);
  if (op == NativeOp::Div) {
    shr(eax, 31);
    lea(eax, ptr[rax * 2 - 1]);
  } else {
    mov(eax, 0xFFFFFFFF);
  }
  mov(cpu32(lay.lo), eax);
  L(done);
  lea(rax, ptr[now + cpu_detail::kDivideCycles]);
  mov(cpu64(lay.muldiv_ready_at), rax);
}

}  // namespace psx
