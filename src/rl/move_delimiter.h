// The seed's move delimiter (§3.2.4, §4.1.3), in emulated frames: after an action a timer is set
// to an initial delay; every frame in which a watched variable (camera, score) changes or the
// audio output is not silent resets it to the delay; the move is over when it runs out. An upper
// bound ends a move that never settles, and says so.
#pragma once
#include <cstdint>

namespace psxrl::rl {

struct DelimiterSettings {
  std::uint32_t initial_delay = 6;
  std::uint32_t delay = 4;
  std::uint32_t max_frames = 600;
};

class MoveDelimiter {
 public:
  void begin(const DelimiterSettings& s) {
    settings_ = s;
    remaining_ = s.initial_delay;
    frames_ = 0;
    hit_bound_ = false;
  }
  // After each emulated frame of the move: was anything watched active? True when the move is over.
  bool frame(bool activity) {
    ++frames_;
    if (activity) remaining_ = settings_.delay;
    else if (remaining_ > 0) --remaining_;
    if (remaining_ == 0) return true;
    hit_bound_ = frames_ >= settings_.max_frames;
    return hit_bound_;
  }
  std::uint32_t frames() const { return frames_; }
  bool hit_bound() const { return hit_bound_; }

 private:
  DelimiterSettings settings_;
  std::uint32_t remaining_ = 0;
  std::uint32_t frames_ = 0;
  bool hit_bound_ = false;
};

}  // namespace psxrl::rl
