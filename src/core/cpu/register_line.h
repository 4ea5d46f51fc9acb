// The registers of a loop that adds the same step to each of them every iteration lie on a line:
// after j iterations from `from`, register r holds from[r] + j*step[r] (mod 2^32). Idle skipping
// (idle_skip.h) uses this to recognise a loop it has proven before, met again j iterations on.
#pragma once
#include <array>

#include "core/types.h"

namespace psx {

class RegisterLine {
 public:
  RegisterLine() = default;
  // The line through the registers before and after one iteration.
  RegisterLine(const std::array<u32, 32>& before, const std::array<u32, 32>& after) {
    for (u32 r = 0; r < 32; ++r) {
      steps_[r] = after[r] - before[r];
      if (steps_[r] == 0) {
        fixed_ |= 1u << r;
        continue;
      }
      moving_[moving_count_++] = r;
      // j is solved with the step that has the fewest trailing zero bits, t: it fixes j modulo
      // 2^(32-t) (a multiple of an odd number is invertible modulo a power of two).
      const u32 tz = static_cast<u32>(__builtin_ctz(steps_[r]));
      if (tz < zeros_) zeros_ = tz, pick_ = r, inverse_ = odd_inverse(steps_[r] >> tz);
    }
  }

  // Whether one iteration from `before` to `after` added this line's steps.
  bool same_steps(const std::array<u32, 32>& before, const std::array<u32, 32>& after) const {
    u32 differ = 0;  // accumulated without branching, which the compiler vectorises
    for (u32 r = 0; r < 32; ++r) differ |= (after[r] - before[r]) ^ steps_[r];
    return differ == 0;
  }

  // Whether no register moves (every iteration starts from the same registers).
  bool still() const { return moving_count_ == 0; }

  // regs + n*step, in place (the registers that do not move add 0).
  void advance(std::array<u32, 32>& regs, u32 n) const {
    for (u32 i = 0; i < moving_count_; ++i) regs[moving_[i]] += n * steps_[moving_[i]];
  }

  // The smallest j with from + j*step == to, if there is one (0 when no register moves); the
  // registers in `any` (bit r for register r) may differ where their step is zero.
  bool iterations(const std::array<u32, 32>& from, const std::array<u32, 32>& to, u32& j, u32 any = 0) const {
    for (u32 compare = fixed_ & ~any; compare != 0; compare &= compare - 1) {
      const u32 r = static_cast<u32>(__builtin_ctz(compare));
      if (from[r] != to[r]) return false;
    }
    j = 0;
    if (moving_count_ == 0) return true;
    const u32 diff = to[pick_] - from[pick_];
    if (diff & ((1u << zeros_) - 1)) return false;
    j = (diff >> zeros_) * inverse_;
    if (zeros_) j &= (1u << (32 - zeros_)) - 1;
    for (u32 i = 0; i < moving_count_; ++i) {
      const u32 r = moving_[i];
      if (from[r] + j * steps_[r] != to[r]) return false;
    }
    return true;
  }

 private:
  // The inverse of an odd number modulo 2^32 (Newton's iteration doubles the correct low bits;
  // a * a == 1 mod 8 gives the first three).
  static u32 odd_inverse(u32 a) {
    u32 x = a;
    for (int i = 0; i < 4; ++i) x *= 2 - a * x;
    return x;
  }

  std::array<u32, 32> steps_{};
  u32 fixed_ = 0;                 // bit r: the loop leaves register r as it is
  std::array<u32, 32> moving_{};  // the others, moving_count_ of them
  u32 moving_count_ = 0;
  u32 pick_ = 0, zeros_ = 32, inverse_ = 0;
};

}  // namespace psx
