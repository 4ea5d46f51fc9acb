// x86-64 code for compiled blocks, generated with xbyak into one executable buffer. A block is
// a sequence of steps; each step is a call step.fn(context, step.pc, step.word) and the block
// returns at the first call that answers false. Xbyak stays inside block_emitter.cpp.
#pragma once
#include <cstddef>
#include <memory>
#include <span>

#include "core/types.h"

namespace psx {

class BlockEmitter {
 public:
  using StepFn = bool (*)(void* context, u32 pc, u32 word);
  using BlockFn = void (*)();
  struct Step {
    u32 pc;
    u32 word;  // the instruction compiled
    StepFn fn;
  };

  explicit BlockEmitter(size_t buffer_bytes);
  ~BlockEmitter();
  BlockEmitter(const BlockEmitter&) = delete;
  BlockEmitter& operator=(const BlockEmitter&) = delete;

  // The block's entry point, or nullptr when the buffer has no room left for it (clear() then
  // makes room; every block emitted before is gone).
  BlockFn emit(void* context, std::span<const Step> steps);
  void clear();
  size_t bytes_used() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace psx
