// RIFF/WAVE files of 16-bit PCM: writing the SPU's output (atomically: temporary file, then
// rename) and reading sound effects for the ADPCM encoder, with precise errors for bad files.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "core/audio_fifo.h"
#include "core/types.h"

namespace psx::spu {

// A malformed or unreadable WAV file; the message names the file, the byte offset and what was
// expected there.
class WavError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct WavData {
  u32 sample_rate = 0;
  u16 channels = 0;
  std::vector<s16> samples;  // interleaved
};

// Reads a 16-bit PCM WAV file (any channel count).
WavData read_wav(const std::string& path);

// Writes stereo 16-bit samples; throws WavError when the file cannot be written.
void write_wav(const std::string& path, const StereoSample* samples, size_t count, u32 sample_rate = 44100);

}  // namespace psx::spu
