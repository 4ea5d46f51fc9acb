// x86-64 code for compiled blocks, generated with xbyak into one executable buffer. A block is a
// sequence of steps. A call step is `call step.fn(context, step.pc, step.word)`, and the block
// returns at the first call that answers false. A run of native steps (register-only ALU
// instructions, NativeOp) is a segment: a guard call first checks that the whole run may execute
// as native code (native_segments in recompiler_ops.h says when), and the segment then runs
// inline, doing what CpuT::execute_at_pc() does for each instruction; when the guard refuses, the
// segment's steps run as calls instead. Xbyak stays inside block_emitter.cpp.
#pragma once
#include <cstddef>
#include <memory>
#include <span>

#include "core/types.h"

namespace psx {

// The instructions emitted as native code (cpu_execute.h gives their semantics).
enum class NativeOp : u8 {
  None,  // a call step
  Addiu, Slti, Sltiu, Andi, Ori, Xori, Lui,
  Sll, Srl, Sra, Sllv, Srlv, Srav, Addu, Subu, And, Or, Xor, Nor, Slt, Sltu,
};

class BlockEmitter {
 public:
  using StepFn = bool (*)(void* context, u32 pc, u32 word);
  // Whether the segment described by `segment` ({first pc, count, the compiled words}) may run as
  // native code now.
  using GuardFn = bool (*)(void* context, const u32* segment);
  using BlockFn = void (*)();
  struct Step {
    u32 pc;
    u32 word;  // the instruction compiled
    StepFn fn;
    NativeOp native = NativeOp::None;
  };
  // Where native code finds the CPU's state: byte offsets of CpuT's fields from the context, and
  // of the scheduler's time and deadline from `sched` (u32 fields unless noted).
  struct Layout {
    void* context;
    void* sched;
    GuardFn guard;
    int regs, pc, next_pc, current_pc, load_reg, load_val, shadow_reg;
    int in_delay_slot, next_in_delay;  // bool
    int instructions, load_done_at;    // u64
    int now, deadline;                 // u64, from sched
  };

  explicit BlockEmitter(size_t buffer_bytes);
  ~BlockEmitter();
  BlockEmitter(const BlockEmitter&) = delete;
  BlockEmitter& operator=(const BlockEmitter&) = delete;

  // The block's entry point, or nullptr when the buffer has no room left for it (clear() then
  // makes room; every block emitted before is gone).
  BlockFn emit(const Layout& layout, std::span<const Step> steps);
  void clear();
  size_t bytes_used() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace psx
