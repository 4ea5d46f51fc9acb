// MFCC computation with Eigen's FFT (seed §3.2; conventions of python_speech_features).
#include "spu/audio_features.h"

#include <cmath>
#include <complex>
#include <limits>
#include <vector>

#include <unsupported/Eigen/FFT>

namespace psx::spu {
namespace {

u32 round_half_up(double v) { return static_cast<u32>(std::floor(v + 0.5)); }

// Triangular filters between mel-spaced FFT bins: rows are filters, columns bins 0..N/2.
Eigen::MatrixXd mel_filterbank(const MfccOptions& o, u32 nfft) {
  const u32 nbins = nfft / 2 + 1;
  const double low = hz_to_mel(0.0), high = hz_to_mel(o.sample_rate / 2.0);
  std::vector<u32> bin(o.num_filters + 2);
  for (u32 j = 0; j < bin.size(); ++j) {
    const double mel = low + (high - low) * j / (o.num_filters + 1);
    bin[j] = static_cast<u32>(std::floor((nfft + 1) * mel_to_hz(mel) / o.sample_rate));
  }
  Eigen::MatrixXd fb = Eigen::MatrixXd::Zero(o.num_filters, nbins);
  for (u32 j = 0; j < o.num_filters; ++j) {
    for (u32 i = bin[j]; i < bin[j + 1] && i < nbins; ++i) fb(j, i) = double(i - bin[j]) / (bin[j + 1] - bin[j]);
    for (u32 i = bin[j + 1]; i < bin[j + 2] && i < nbins; ++i)
      fb(j, i) = double(bin[j + 2] - i) / (bin[j + 2] - bin[j + 1]);
  }
  return fb;
}

}  // namespace

double hz_to_mel(double hz) { return 2595.0 * std::log10(1.0 + hz / 700.0); }
double mel_to_hz(double mel) { return 700.0 * (std::pow(10.0, mel / 2595.0) - 1.0); }
u32 mfcc_frame_length(const MfccOptions& o) { return round_half_up(o.frame_seconds * o.sample_rate); }
u32 mfcc_step_length(const MfccOptions& o) { return round_half_up(o.step_seconds * o.sample_rate); }
u32 mfcc_fft_size(const MfccOptions& o) {
  if (o.fft_size) return o.fft_size;
  u32 n = 1;
  while (n < mfcc_frame_length(o)) n <<= 1;
  return n;
}

Eigen::MatrixXf mfcc(const float* mono, size_t count, const MfccOptions& o) {
  const u32 frame = mfcc_frame_length(o), step = mfcc_step_length(o), nfft = mfcc_fft_size(o);
  if (count == 0 || frame == 0 || step == 0) return Eigen::MatrixXf(0, o.num_coefficients);
  const size_t frames = count <= frame ? 1 : 1 + (count - frame + step - 1) / step;

  // Pre-emphasis, zero-padded to whole frames.
  std::vector<double> x((frames - 1) * step + frame, 0.0);
  for (size_t n = 0; n < count; ++n) x[n] = mono[n] - (n ? o.preemphasis * mono[n - 1] : 0.0);

  const Eigen::MatrixXd fb = mel_filterbank(o, nfft);
  const double eps = std::numeric_limits<double>::epsilon();
  const u32 nf = o.num_filters;
  Eigen::FFT<double> fft;
  std::vector<double> buf(nfft);
  std::vector<std::complex<double>> spec;
  Eigen::VectorXd power(nfft / 2 + 1);
  Eigen::MatrixXf out(frames, o.num_coefficients);
  for (size_t f = 0; f < frames; ++f) {
    std::fill(buf.begin(), buf.end(), 0.0);
    std::copy_n(x.begin() + f * step, std::min<u32>(frame, nfft), buf.begin());
    fft.fwd(spec, buf);
    for (u32 k = 0; k <= nfft / 2; ++k) power[k] = std::norm(spec[k]) / nfft;
    Eigen::VectorXd energies = fb * power;
    for (u32 j = 0; j < nf; ++j) energies[j] = std::log(energies[j] > 0 ? energies[j] : eps);
    const double frame_energy = power.sum();
    for (u32 k = 0; k < o.num_coefficients; ++k) {
      // Orthonormal DCT-II of the log filter energies, then the sinusoidal lifter.
      double c = 0;
      for (u32 n = 0; n < nf; ++n) c += energies[n] * std::cos(M_PI * k * (2 * n + 1) / (2.0 * nf));
      c *= std::sqrt((k == 0 ? 1.0 : 2.0) / nf);
      if (o.lifter) c *= 1.0 + (o.lifter / 2.0) * std::sin(M_PI * k / o.lifter);
      out(f, k) = static_cast<float>(c);
    }
    if (o.num_coefficients) out(f, 0) = static_cast<float>(std::log(frame_energy > 0 ? frame_energy : eps));
  }
  return out;
}

Eigen::MatrixXf mfcc(const StereoSample* samples, size_t count, const MfccOptions& o) {
  std::vector<float> mono(count);
  for (size_t i = 0; i < count; ++i) mono[i] = (static_cast<float>(samples[i].left) + samples[i].right) * 0.5f;
  return mfcc(mono.data(), count, o);
}

}  // namespace psx::spu
