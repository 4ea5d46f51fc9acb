// Sound for the play window: the SPU's 44.1 kHz stereo output queued to an SDL audio device. The
// queue's length also paces play to real time (the device drains it at the console's rate).
#pragma once
#include <SDL.h>

#include <span>
#include <string>

#include "core/audio_fifo.h"

namespace psxrl::frontend {

class SdlAudio {
 public:
  static constexpr int kRate = 44100;  // the SPU's output rate (psx-spx "SPU")

  // Opens the default output device; throws std::runtime_error with SDL's reason when it cannot.
  SdlAudio();
  ~SdlAudio();
  SdlAudio(const SdlAudio&) = delete;
  SdlAudio& operator=(const SdlAudio&) = delete;

  void queue(std::span<const psx::StereoSample> samples);
  // Seconds of sound queued and not yet played.
  double queued_seconds() const;
  // Drops what is queued (pausing should silence at once).
  void clear();
  // The SDL driver in use, e.g. "pulseaudio" or "dummy".
  std::string driver() const;

 private:
  SDL_AudioDeviceID device_ = 0;
};

}  // namespace psxrl::frontend
