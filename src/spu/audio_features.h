// Audio features for agents: mel-frequency cepstral coefficients as the seed computed them
// (§3.2, with python_speech_features' conventions: pre-emphasis 0.97, rectangular frames,
// power spectrum |FFT|^2/N, 26 triangular mel filters, log, orthonormal DCT-II, lifter 22, and
// the log frame energy in place of the 0th coefficient). Frames are 25 ms with an 11.6 ms step;
// 13 coefficients; mel(f) = 2595*log10(1 + f/700). The FFT is Eigen's.
#pragma once
#include <cstddef>

#include <Eigen/Dense>

#include "core/audio_fifo.h"
#include "core/types.h"

namespace psx::spu {

struct MfccOptions {
  u32 sample_rate = 44100;
  double frame_seconds = 0.025;
  double step_seconds = 0.0116;
  u32 num_coefficients = 13;
  u32 num_filters = 26;
  // 0 picks the smallest power of two holding a whole frame (2048 at 44.1 kHz), so no frame is
  // truncated (the seed's library default of 512 would cut 25 ms frames short).
  u32 fft_size = 0;
  double preemphasis = 0.97;
  u32 lifter = 22;
};

// Frame and step lengths in samples (rounded half up, as python_speech_features does).
u32 mfcc_frame_length(const MfccOptions& o);
u32 mfcc_step_length(const MfccOptions& o);
u32 mfcc_fft_size(const MfccOptions& o);
double hz_to_mel(double hz);
double mel_to_hz(double mel);

// One row per frame, one column per coefficient. A signal shorter than a frame gives one
// zero-padded frame; an empty signal gives no rows.
Eigen::MatrixXf mfcc(const float* mono, size_t count, const MfccOptions& options = {});
// Stereo SPU output, averaged to mono first.
Eigen::MatrixXf mfcc(const StereoSample* samples, size_t count, const MfccOptions& options = {});

}  // namespace psx::spu
