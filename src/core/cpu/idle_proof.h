// The proof behind idle-loop skipping (idle_skip.h): given one recorded iteration of a loop and
// the registers before and after it, shows that iteration k (k = 0 is the one about to start)
// begins with every register at after + k*step (step = after - before, modulo 2^32) and follows
// the recorded path, for every k up to a bound. Register values are tracked as base + k*step:
// addition, subtraction and left shifts keep that form exactly (modulo 2^32); other operations
// keep it only for constants. A comparison of such values keeps its outcome while neither side
// wraps and their difference does not change sign, which bounds k; equality likewise. Words of
// memory the loop stores to (a counter in a C `volatile` variable) are tracked like registers.
#pragma once
#include <array>

#include "core/types.h"

namespace psx {

// One executed instruction of the recorded iteration.
struct IdleStep {
  u32 pc;
  u32 instr;
  u32 addr;        // loads and stores: the address accessed
  u32 load_value;  // loads: the value delivered (memory cannot change before an event but by the loop)
  u32 load_bits;   // ... and which bits of it cannot (the others count time, e.g. JOY_STAT's baud timer)
  u32 cell = 0;    // loads and stores of a word the loop stores to: 1 + its index in IdleCells
};

// The words of RAM or the scratchpad a loop iteration stores to, by location (what identifies a
// word whichever mirror or segment addresses it: IdleSkip's business), with the address of its
// first store and its values before and after the recorded iteration.
struct IdleCells {
  static constexpr u32 kMax = 4;
  u32 count = 0;
  std::array<u32, kMax> location{}, vaddr{}, before{}, after{};
  // The index of the cell at `loc`, or -1.
  int find(u32 loc) const {
    for (u32 c = 0; c < count; ++c)
      if (location[c] == loc) return static_cast<int>(c);
    return -1;
  }
};

class IdleProof {
 public:
  // What the loop may contain: ALU operations without traps, loads, word stores, branches and
  // jumps.
  enum class Kind { Alu, Load, Store, Branch, Other };
  static Kind classify(u32 instr);

  // `before`/`after`: the registers at the head before and after the recorded iteration;
  // `load_reg`/`load_val`: the load in flight at the head (register 0 = none); `cells`: the words
  // it stores to (the path's steps name them).
  IdleProof(const std::array<u32, 32>& before, const std::array<u32, 32>& after, u32 load_reg, u32 load_val,
            const IdleCells& cells);

  // Whether the path repeats; max_k() then bounds the iterations k = 0..max_k that provably do.
  bool run(const IdleStep* path, u32 n);
  u64 max_k() const { return max_k_; }

 private:
  // base + k*step when known; a constant (step 0) may have only some bits known.
  struct Val {
    u32 base = 0;
    u32 step = 0;
    bool known = true;
    u32 bits = ~0u;  // the known bits of a constant
    bool affine() const { return known && bits == ~0u; }
    bool constant() const { return affine() && step == 0; }
  };
  static Val unknown() { return {0, 0, false, 0}; }
  static Val constant(u32 v) { return {v, 0, true, ~0u}; }
  static Val partial(u32 v, u32 bits) { return {v & bits, 0, true, bits}; }

  void limit(u64 k) { max_k_ = k < max_k_ ? k : max_k_; }
  void no_wrap(const Val& v, bool sign);
  bool less(const Val& a, const Val& b, bool sign);
  bool equal(const Val& a, const Val& b);

  Val add(const Val& a, const Val& b);
  Val compare(const Val& a, const Val& b, bool sign);
  bool alu(u32 instr);
  bool special(u32 instr);
  bool control(const IdleStep* path, u32 n, u32 i);
  bool memory(const IdleStep& step, bool store);
  void write(u32 r, const Val& v);
  void delayed_load(u32 r, const Val& v);
  Val and_mask(const Val& v, u32 mask);

  std::array<Val, 32> regs_{};
  std::array<u32, 32> after_{};
  std::array<u32, 32> steps_{};
  std::array<Val, IdleCells::kMax> cells_{};  // the stored words, as registers
  IdleCells cell_line_;                       // ... and their values before and after
  u32 load_reg_ = 0, new_reg_ = 0;  // the load landing after the current instruction, the one it issues
  Val load_val_, new_val_;
  u32 start_load_reg_ = 0, start_load_val_ = 0;
  u64 max_k_ = ~u64{0};
};

}  // namespace psx
