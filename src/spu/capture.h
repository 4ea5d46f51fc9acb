// Audio capture for agents (the seed's PSXPY recording, §2.5/§3.1.5, done in-process and exact
// to the sample): start/stop a recording of the SPU output with early amplitude-based cropping
// (recording begins at the first loud sample), amplitude-based termination (it ends after a
// quiet period) and late cropping (it is cut to a tail after the last loud sample).
#pragma once
#include <cstdlib>
#include <vector>

#include "core/audio_fifo.h"
#include "core/types.h"

namespace psx::spu {

struct CaptureOptions {
  // A sample is loud when either channel's magnitude reaches this.
  s32 threshold = 1;
  // Stop after this many consecutive quiet samples once recording began (0: only stop()).
  u32 silence_samples = 0;
  // Late cropping keeps this many samples after the last loud one.
  u32 tail_samples = 0;
};

class AudioCapture {
 public:
  enum class State : u8 { Idle, WaitingForSound, Recording, Finished };

  void start(const CaptureOptions& options);
  // Appends one output sample (called by the SPU for every sample while capturing).
  void push(StereoSample s) {
    if (state_ == State::WaitingForSound || state_ == State::Recording) record(s);
  }
  // Ends the recording if it still runs and hands it over, cropped; the capture becomes idle.
  std::vector<StereoSample> stop();

  State state() const { return state_; }
  bool active() const { return state_ == State::WaitingForSound || state_ == State::Recording; }
  // The recording so far (before late cropping while it still runs).
  const std::vector<StereoSample>& samples() const { return samples_; }

 private:
  bool loud(StereoSample s) const {
    return std::abs(static_cast<s32>(s.left)) >= options_.threshold ||
           std::abs(static_cast<s32>(s.right)) >= options_.threshold;
  }
  void record(StereoSample s);
  void finish();

  CaptureOptions options_;
  State state_ = State::Idle;
  std::vector<StereoSample> samples_;
  size_t last_loud_ = 0;  // index of the last loud sample in samples_
  u32 quiet_run_ = 0;
};

}  // namespace psx::spu
