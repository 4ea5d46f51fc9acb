// SDL audio output (sdl_audio.h). The device is opened for exactly the SPU's format (signed
// 16-bit stereo at 44.1 kHz, which is StereoSample's layout); SDL converts if the hardware wants
// another, so samples are queued as they come.
#include "frontend/sdl_audio.h"

#include <stdexcept>

namespace psxrl::frontend {

SdlAudio::SdlAudio() {
  if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0)
    throw std::runtime_error(std::string("cannot start SDL audio: ") + SDL_GetError());
  SDL_AudioSpec want{};
  want.freq = kRate;
  want.format = AUDIO_S16SYS;
  want.channels = 2;
  want.samples = 1024;  // ~23 ms per device buffer: low latency without underruns
  device_ = SDL_OpenAudioDevice(nullptr, 0, &want, nullptr, 0);
  if (device_ == 0) {
    std::string why = SDL_GetError();
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
    throw std::runtime_error("cannot open an audio device: " + why);
  }
  SDL_PauseAudioDevice(device_, 0);
}

SdlAudio::~SdlAudio() {
  SDL_CloseAudioDevice(device_);
  SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

void SdlAudio::queue(std::span<const psx::StereoSample> samples) {
  static_assert(sizeof(psx::StereoSample) == 4, "StereoSample must be two packed 16-bit samples");
  if (!samples.empty()) SDL_QueueAudio(device_, samples.data(), static_cast<Uint32>(samples.size_bytes()));
}

double SdlAudio::queued_seconds() const {
  return static_cast<double>(SDL_GetQueuedAudioSize(device_)) / (kRate * sizeof(psx::StereoSample));
}

void SdlAudio::clear() { SDL_ClearQueuedAudio(device_); }

std::string SdlAudio::driver() const {
  const char* d = SDL_GetCurrentAudioDriver();
  return d ? d : "?";
}

}  // namespace psxrl::frontend
