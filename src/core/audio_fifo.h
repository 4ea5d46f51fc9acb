// A fixed-size ring of stereo 16-bit sample frames at 44.1 kHz: the CD-ROM block pushes decoded
// CD-DA and XA audio, the SPU pops one frame per output sample and mixes it as its CD input.
#pragma once
#include <array>
#include <functional>

#include "core/state.h"
#include "core/types.h"

namespace psx {

struct StereoSample {
  s16 left = 0;
  s16 right = 0;
};

class AudioFifo {
 public:
  static constexpr u32 kCapacity = 8192;  // ~186 ms at 44.1 kHz, more than one XA sector's worth

  // Called before every push: the SPU produces its samples lazily and must first pop what its
  // samples due so far would have popped (spu/spu.h), or a full FIFO would drop the wrong frames
  // and the samples would hear the pushed frames early.
  std::function<void()> before_push;

  bool push(StereoSample s) {
    if (before_push) before_push();
    if (count_ == kCapacity) return false;
    buf_[(head_ + count_) % kCapacity] = s;
    ++count_;
    return true;
  }
  // An empty FIFO reads as silence.
  StereoSample pop() {
    if (count_ == 0) return {};
    StereoSample s = buf_[head_];
    head_ = (head_ + 1) % kCapacity;
    --count_;
    return s;
  }
  u32 size() const { return count_; }
  void clear() { head_ = count_ = 0; }

  void do_state(StateIO& s) {
    s.section("AFIF", 1);
    s.pod(buf_);
    s.pod(head_);
    s.pod(count_);
    if (s.loading() && (head_ >= kCapacity || count_ > kCapacity)) s.fail("audio FIFO indices out of range");
    s.end_section("AFIF");
  }

 private:
  std::array<StereoSample, kCapacity> buf_{};
  u32 head_ = 0;
  u32 count_ = 0;
};

}  // namespace psx
