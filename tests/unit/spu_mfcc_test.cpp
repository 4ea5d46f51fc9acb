// MFCC features against a reference written here from the definition: a direct O(N^2) DFT,
// mel filters from mel(f) = 2595*log10(1 + f/700), log, DCT-II, lifter, log energy as c0
// (python_speech_features conventions, seed §3.2).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "spu/audio_features.h"

using namespace psx;
using namespace psx::spu;

namespace {

std::vector<std::vector<double>> reference_mfcc(const std::vector<float>& sig) {
  const int sr = 44100, frame = 1103, step = 512, nfft = 2048, nfilt = 26, ncep = 13, lifter = 22;
  std::vector<double> x(sig.size());
  for (size_t n = 0; n < sig.size(); ++n) x[n] = sig[n] - (n ? 0.97 * sig[n - 1] : 0.0);
  const int frames = sig.size() <= size_t(frame) ? 1 : 1 + int(std::ceil(double(sig.size() - frame) / step));
  x.resize((frames - 1) * step + frame, 0.0);

  auto mel = [](double f) { return 2595 * std::log10(1 + f / 700); };
  auto hz = [](double m) { return 700 * (std::pow(10, m / 2595) - 1); };
  std::vector<int> bin(nfilt + 2);
  for (int j = 0; j < nfilt + 2; ++j) bin[j] = int(std::floor((nfft + 1) * hz(mel(sr / 2.0) * j / (nfilt + 1)) / sr));

  std::vector<std::vector<double>> out;
  for (int f = 0; f < frames; ++f) {
    std::vector<double> power(nfft / 2 + 1);
    double energy = 0;
    for (int k = 0; k <= nfft / 2; ++k) {
      std::complex<double> acc = 0;
      for (int t = 0; t < frame; ++t) acc += x[f * step + t] * std::polar(1.0, -2 * M_PI * double(k) * t / nfft);
      power[k] = std::norm(acc) / nfft;
      energy += power[k];
    }
    std::vector<double> logfb(nfilt);
    for (int j = 0; j < nfilt; ++j) {
      double e = 0;
      for (int i = bin[j]; i < bin[j + 1]; ++i) e += power[i] * (i - bin[j]) / double(bin[j + 1] - bin[j]);
      for (int i = bin[j + 1]; i < bin[j + 2]; ++i) e += power[i] * (bin[j + 2] - i) / double(bin[j + 2] - bin[j + 1]);
      logfb[j] = std::log(e);
    }
    std::vector<double> c(ncep);
    for (int k = 0; k < ncep; ++k) {
      double s = 0;
      for (int n = 0; n < nfilt; ++n) s += logfb[n] * std::cos(M_PI * k * (2 * n + 1) / (2.0 * nfilt));
      c[k] = s * std::sqrt((k ? 2.0 : 1.0) / nfilt) * (1 + lifter / 2.0 * std::sin(M_PI * k / lifter));
    }
    c[0] = std::log(energy);
    out.push_back(c);
  }
  return out;
}

}  // namespace

TEST(SpuMfcc, FrameGeometry) {
  MfccOptions o;
  EXPECT_EQ(mfcc_frame_length(o), 1103u);  // 25 ms * 44100 = 1102.5, rounded half up
  EXPECT_EQ(mfcc_step_length(o), 512u);    // 11.6 ms * 44100 = 511.56
  EXPECT_EQ(mfcc_fft_size(o), 2048u);
  EXPECT_NEAR(hz_to_mel(700), 2595 * std::log10(2.0), 1e-9);
  EXPECT_NEAR(mel_to_hz(hz_to_mel(1234.5)), 1234.5, 1e-9);
}

TEST(SpuMfcc, ToneMatchesDftReference) {
  // A 440 Hz tone plus a weaker 3 kHz one, 3000 samples: 1 + ceil((3000-1103)/512) = 5 frames.
  std::vector<float> sig(3000);
  for (size_t n = 0; n < sig.size(); ++n)
    sig[n] = float(10000 * std::sin(2 * M_PI * 440 * n / 44100) + 2000 * std::sin(2 * M_PI * 3000 * n / 44100));
  Eigen::MatrixXf got = mfcc(sig.data(), sig.size());
  auto want = reference_mfcc(sig);
  ASSERT_EQ(got.rows(), 5);
  ASSERT_EQ(got.cols(), 13);
  for (int f = 0; f < 5; ++f)
    for (int k = 0; k < 13; ++k) EXPECT_NEAR(got(f, k), want[f][k], 1e-3 * (1 + std::abs(want[f][k]))) << f << "," << k;
}

TEST(SpuMfcc, StereoIsAveragedAndShortSignalsGiveOneFrame) {
  std::vector<StereoSample> st(800);
  std::vector<float> mono(800);
  for (size_t n = 0; n < st.size(); ++n) {
    st[n] = {static_cast<s16>(n * 13 % 2000), static_cast<s16>(n * 7 % 1000)};
    mono[n] = (st[n].left + st[n].right) / 2.0f;
  }
  Eigen::MatrixXf a = mfcc(st.data(), st.size());
  Eigen::MatrixXf b = mfcc(mono.data(), mono.size());
  ASSERT_EQ(a.rows(), 1);
  EXPECT_TRUE(a.isApprox(b));
  EXPECT_EQ(mfcc(mono.data(), 0).rows(), 0);
}
