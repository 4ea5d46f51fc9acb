// SPU benchmark: generates emulated seconds of audio with all 24 voices playing looped ADPCM
// (plus reverb), and MFCCs of one second of audio; prints host time per emulated second.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/audio_fifo.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "spu/adpcm.h"
#include "spu/audio_features.h"
#include "spu/spu.h"

int main() {
  using namespace psx;
  using Clock = std::chrono::steady_clock;
  Scheduler sched;
  InterruptController irq;
  AudioFifo cd;
  Spu spu(sched, irq, cd);
  auto w16 = [&](u32 addr, u16 v) { spu.io_write(addr - Spu::kBase, v, 2); };

  std::vector<s16> pcm(28 * 40);
  for (size_t i = 0; i < pcm.size(); ++i) pcm[i] = static_cast<s16>(8000 * std::sin(2 * M_PI * i / 40.0));
  spu::AdpcmEncodeOptions loop;
  loop.loop = true;
  const std::vector<u8> blocks = spu::encode_adpcm(pcm.data(), pcm.size(), loop);
  for (size_t i = 0; i < blocks.size(); ++i) spu.ram()[0x1000 + i] = blocks[i];

  w16(0x1F801DAA, 0xC080);
  w16(0x1F801D80, 0x3FFF);
  w16(0x1F801D82, 0x3FFF);
  w16(0x1F801D84, 0x2000);
  w16(0x1F801D86, 0x2000);
  w16(0x1F801DA2, 0xE000);
  for (u32 v = 0; v < 24; ++v) {
    const u32 base = 0x1F801C00 + v * 16;
    w16(base + 0x0, 0x0400);
    w16(base + 0x2, 0x0400);
    w16(base + 0x4, static_cast<u16>(0x0800 + v * 0x80));
    w16(base + 0x6, 0x1000 / 8);
    w16(base + 0x8, 0x00FF);
    w16(base + 0xA, 0x1FC0);
  }
  w16(0x1F801D98, 0xFFFF);
  w16(0x1F801D9A, 0x00FF);
  w16(0x1F801D88, 0xFFFF);
  w16(0x1F801D8A, 0x00FF);

  const int seconds = 10;
  std::vector<StereoSample> out, all;
  const auto t0 = Clock::now();
  for (int s = 0; s < seconds * 60; ++s) {  // drain once per frame, as an environment would
    for (u32 i = 0; i < Spu::kSampleRate / 60; ++i) {
      sched.advance(Spu::kCyclesPerSample);
      sched.run_due_events();
    }
    spu.take_samples(out);
    all.insert(all.end(), out.begin(), out.end());
  }
  const double secs = std::chrono::duration<double>(Clock::now() - t0).count();
  std::printf("spu: %d emulated s (24 voices + reverb) in %.3f s host: %.2f ms per emulated second, %.0fx real time\n",
              seconds, secs, 1000 * secs / seconds, seconds / secs);

  const auto t1 = Clock::now();
  Eigen::MatrixXf m = spu::mfcc(all.data(), Spu::kSampleRate);
  const double msecs = std::chrono::duration<double>(Clock::now() - t1).count();
  std::printf("mfcc: 1 s of audio (%ld frames x %ld coefficients) in %.2f ms\n", static_cast<long>(m.rows()),
              static_cast<long>(m.cols()), 1000 * msecs);
  return 0;
}
