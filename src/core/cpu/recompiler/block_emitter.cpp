// Emits compiled blocks (block_emitter.h) with xbyak (System V x86-64 calling convention).
#include "core/cpu/recompiler/block_emitter.h"

#include <xbyak/xbyak.h>

namespace psx {

struct BlockEmitter::Impl : Xbyak::CodeGenerator {
  explicit Impl(size_t bytes) : Xbyak::CodeGenerator(bytes), capacity(bytes) {}
  const size_t capacity;
};

BlockEmitter::BlockEmitter(size_t buffer_bytes) : impl_(std::make_unique<Impl>(buffer_bytes)) {}
BlockEmitter::~BlockEmitter() = default;

BlockEmitter::BlockFn BlockEmitter::emit(void* context, std::span<const Step> steps) {
  // An upper bound on one step's code (mov r64 r64, mov r32 imm32 twice, mov r64 imm64, call,
  // test, jcc).
  constexpr size_t kStepBytes = 40, kFrameBytes = 32;
  Impl& g = *impl_;
  if (g.getSize() + kFrameBytes + kStepBytes * steps.size() > g.capacity) return nullptr;
  g.align(16);
  const auto entry = g.getCurr<BlockFn>();
  Xbyak::Label done;
  // rbx (callee-saved) holds the context across the calls; pushing it also leaves the stack
  // 16-byte aligned at each call, as the ABI wants.
  g.push(g.rbx);
  g.mov(g.rbx, reinterpret_cast<u64>(context));
  for (const Step& s : steps) {
    g.mov(g.rdi, g.rbx);
    g.mov(g.esi, s.pc);
    g.mov(g.edx, s.word);
    g.mov(g.rax, reinterpret_cast<u64>(s.fn));
    g.call(g.rax);
    g.test(g.al, g.al);
    g.jz(done, Xbyak::CodeGenerator::T_NEAR);
  }
  g.L(done);
  g.pop(g.rbx);
  g.ret();
  return entry;
}

void BlockEmitter::clear() { impl_->reset(); }

size_t BlockEmitter::bytes_used() const { return impl_->getSize(); }

}  // namespace psx
