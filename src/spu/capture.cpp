// Audio capture with amplitude-based cropping and termination (seed §2.5).
#include "spu/capture.h"

#include <algorithm>
#include <utility>

namespace psx::spu {

void AudioCapture::start(const CaptureOptions& options) {
  options_ = options;
  samples_.clear();
  last_loud_ = 0;
  quiet_run_ = 0;
  state_ = State::WaitingForSound;
}

void AudioCapture::record(StereoSample s) {
  const bool is_loud = loud(s);
  if (state_ == State::WaitingForSound) {
    if (!is_loud) return;  // early cropping: nothing before the first loud sample
    state_ = State::Recording;
  }
  samples_.push_back(s);
  if (is_loud) {
    last_loud_ = samples_.size() - 1;
    quiet_run_ = 0;
    return;
  }
  ++quiet_run_;
  if (options_.silence_samples != 0 && quiet_run_ >= options_.silence_samples) finish();
}

void AudioCapture::finish() {
  if (state_ == State::Recording) {
    const size_t keep = std::min<size_t>(samples_.size(), last_loud_ + 1 + options_.tail_samples);
    samples_.resize(keep);
  }
  state_ = State::Finished;
}

std::vector<StereoSample> AudioCapture::stop() {
  if (active()) finish();
  state_ = State::Idle;
  return std::exchange(samples_, {});
}

}  // namespace psx::spu
