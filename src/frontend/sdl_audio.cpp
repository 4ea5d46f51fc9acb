// SDL audio output (sdl_audio.h). The device is opened for exactly the SPU's format (signed
// 16-bit stereo at 44.1 kHz, which is StereoSample's layout); SDL converts if the hardware wants
// another, so samples are queued as they come.
#include "frontend/sdl_audio.h"

#include <algorithm>
#include <cstring>
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
  want.callback = &SdlAudio::fill;
  want.userdata = this;
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

// The device's thread asks for `bytes` of sound: queued samples, then silence if they run out.
void SDLCALL SdlAudio::fill(void* self, Uint8* stream, int bytes) {
  auto& a = *static_cast<SdlAudio*>(self);
  const size_t want = static_cast<size_t>(bytes) / sizeof(psx::StereoSample);
  const size_t n = std::min(want, a.queue_.size() - a.read_);
  if (n > 0) std::memcpy(stream, a.queue_.data() + a.read_, n * sizeof(psx::StereoSample));  // data() may be null
  std::memset(stream + n * sizeof(psx::StereoSample), 0, static_cast<size_t>(bytes) - n * sizeof(psx::StereoSample));
  a.read_ += n;
}

void SdlAudio::queue(std::span<const psx::StereoSample> samples) {
  static_assert(sizeof(psx::StereoSample) == 4, "StereoSample must be two packed 16-bit samples");
  if (samples.empty()) return;
  SDL_LockAudioDevice(device_);
  queue_.erase(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(read_));  // what was played
  read_ = 0;
  queue_.insert(queue_.end(), samples.begin(), samples.end());
  SDL_UnlockAudioDevice(device_);
}

double SdlAudio::queued_seconds() const {
  SDL_LockAudioDevice(device_);
  const size_t n = queue_.size() - read_;
  SDL_UnlockAudioDevice(device_);
  return static_cast<double>(n) / kRate;
}

void SdlAudio::clear() {
  SDL_LockAudioDevice(device_);
  queue_.clear();
  read_ = 0;
  SDL_UnlockAudioDevice(device_);
}

std::string SdlAudio::driver() const {
  const char* d = SDL_GetCurrentAudioDriver();
  return d ? d : "?";
}

}  // namespace psxrl::frontend
