// Real-time pacing for human play and watching: holds the caller to the console's frame rate
// with the host clock. Only front ends use it; the emulator core never reads a host clock.
#pragma once
#include <chrono>
#include <thread>

namespace psxrl::cli {

class Pacer {
 public:
  explicit Pacer(double frames_per_second)
      : period_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / frames_per_second))),
        next_(Clock::now() + period_) {}

  // Sleeps until the next frame is due. A host that fell more than a few frames behind starts
  // over rather than rushing to catch up.
  void wait_frame() {
    auto now = Clock::now();
    if (now < next_) std::this_thread::sleep_until(next_);
    else if (now - next_ > 4 * period_) next_ = now;
    next_ += period_;
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::duration period_;
  Clock::time_point next_;
};

}  // namespace psxrl::cli
