// Sound for the play window: the SPU's 44.1 kHz stereo output queued to an SDL audio device. The
// queue's length also paces play to real time (the device drains it at the console's rate).
//
// The queue is our own, drained by an SDL audio callback, rather than SDL_QueueAudio: in queue
// mode SDL 2 runs its audio thread on a 64 KiB stack, and a process that also loads libraries with
// large static thread-local storage (OpenBLAS through LibTorch: about 100 KiB in all) cannot
// create that thread ("Couldn't create audio thread"). With a callback SDL uses the default stack.
#pragma once
#include <SDL.h>

#include <span>
#include <string>
#include <vector>

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
  static void SDLCALL fill(void* self, Uint8* stream, int bytes);

  SDL_AudioDeviceID device_ = 0;
  // Samples not yet handed to the device, from `read_`; guarded by SDL_LockAudioDevice.
  std::vector<psx::StereoSample> queue_;
  size_t read_ = 0;
};

}  // namespace psxrl::frontend
