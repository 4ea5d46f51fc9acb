// Native GTE instructions for compiled blocks (emitter_impl.h): CpuT::execute_cop2()'s register
// moves MFC2/CFC2 (the value arrives after a load delay, as a load's does), MTC2/CTC2, and the
// commands (imm25), each after wait_gte() (the CPU waits for the command in progress), calling
// the GTE's own functions from the block without leaving it. A command's duration sets when the
// GTE is next free. The segment's guard has checked SR.CU2 (else the instructions raise
// Coprocessor Unusable through their call steps).
#include "core/cpu/decode.h"
#include "core/cpu/recompiler/emitter_impl.h"
#include "core/gte/gte.h"

namespace psx {

using Impl = BlockEmitter::Impl;

// CpuT::wait_gte(): time goes on to when the GTE's command in progress ends.
void Impl::wait_gte() {
  mov(rcx, cpu64(lay.gte_ready_at));
  cmp(now, rcx);
  cmovb(now, rcx);
}

// Where native code finds byte `offset` of the Gte: rbx-relative where it can, else through rdi.
Xbyak::RegExp Impl::gte_at(u32 offset) {
  if (const auto d = from_context(static_cast<const u8*>(lay.gte) + offset)) return rbx + *d;
  mov(rdi, reinterpret_cast<u64>(lay.gte));
  return rdi + offset;
}

// eax = a GTE data register that reads as field f (Gte::data_field()), as Gte::read_data().
void Impl::gte_read(const Gte::Field& f) {
  const Xbyak::RegExp at = gte_at(f.offset);
  if (f.bytes == 4) mov(eax, dword[at]);
  else if (f.sign) movsx(eax, word[at]);
  else movzx(eax, word[at]);
}

// A GTE data register that writes as field f = value's low bytes, as Gte::write_data().
void Impl::gte_write(const Gte::Field& f, const Xbyak::Reg32& value) {
  const Xbyak::RegExp at = gte_at(f.offset);
  if (f.bytes == 4) mov(dword[at], value);
  else mov(word[at], value.cvt16());
}

// MFC2/CFC2 leave the value in eax (native() makes it the pending load). The data registers
// that are plain fields move natively, the rest through the GTE's functions.
void Impl::cop2(NativeOp op, u32 i) {
  using namespace cpu_detail;
  wait_gte();
  if (op == NativeOp::Mfc2) {
    if (const auto f = Gte::data_field(rd(i), false)) return gte_read(*f);
  } else if (op == NativeOp::Mtc2) {
    if (const auto f = Gte::data_field(rd(i), true)) {
      mov(edx, reg(rt(i)));
      return gte_write(*f, edx);
    }
  }
  mov(rdi, reinterpret_cast<u64>(lay.gte));
  switch (op) {
    case NativeOp::Mfc2:
    case NativeOp::Cfc2:
      mov(esi, rd(i));
      call_leaf(reinterpret_cast<const void*>(op == NativeOp::Mfc2 ? lay.gte_read_data : lay.gte_read_control));
      break;
    case NativeOp::Mtc2:
    case NativeOp::Ctc2:
      mov(esi, rd(i));
      mov(edx, reg(rt(i)));
      call_leaf(reinterpret_cast<const void*>(op == NativeOp::Mtc2 ? lay.gte_write_data : lay.gte_write_control));
      break;
    default: {  // a command, known now: its own function, and the GTE busy for its cycles
      const u32 command = i & 0x1FFFFFF;
      mov(esi, command);
      call_leaf(reinterpret_cast<const void*>(Gte::command_function(command)));
      lea(rax, ptr[now + int(lay.gte_cycles(command))]);
      mov(cpu64(lay.gte_ready_at), rax);
      break;
    }
  }
}

}  // namespace psx
