// psxadpcm: encodes a 16-bit PCM WAV file into PlayStation SPU-ADPCM blocks (raw, 16 bytes per
// 28 samples) with loop flags, ready to upload to sound RAM. Multi-channel input is averaged to
// mono. The sample rate is not stored: play it with VxPitch = rate * 4096 / 44100.
// Exit codes: 0 success, 1 usage error, 2 bad input file or unwritable output.
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "spu/adpcm.h"
#include "spu/wav.h"

namespace {

int usage() {
  std::fprintf(stderr,
               "usage: psxadpcm IN.wav OUT.adpcm [--loop] [--loop-start SAMPLE]\n"
               "  --loop              loop the whole sound (or from --loop-start) instead of one-shot\n"
               "  --loop-start SAMPLE sample index where the loop begins (rounded down to a block)\n");
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> positional;
  psx::spu::AdpcmEncodeOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--loop") {
      options.loop = true;
    } else if (a == "--loop-start" && i + 1 < argc) {
      char* end = nullptr;
      const unsigned long v = std::strtoul(argv[++i], &end, 10);
      if (!end || *end) return usage();
      options.loop = true;
      options.loop_start = static_cast<psx::u32>(v);
    } else if (!a.empty() && a[0] == '-') {
      return usage();
    } else {
      positional.push_back(a);
    }
  }
  if (positional.size() != 2) return usage();

  psx::spu::WavData wav;
  try {
    wav = psx::spu::read_wav(positional[0]);
  } catch (const psx::spu::WavError& e) {
    std::fprintf(stderr, "psxadpcm: %s\n", e.what());
    return 2;
  }
  std::vector<psx::s16> mono(wav.samples.size() / wav.channels);
  for (size_t i = 0; i < mono.size(); ++i) {
    long sum = 0;
    for (psx::u16 c = 0; c < wav.channels; ++c) sum += wav.samples[i * wav.channels + c];
    mono[i] = static_cast<psx::s16>(sum / wav.channels);
  }
  const std::vector<psx::u8> blocks = psx::spu::encode_adpcm(mono.data(), mono.size(), options);
  try {
    psx::write_file_atomically(positional[1], blocks);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "psxadpcm: %s\n", e.what());
    return 2;
  }
  std::printf("%s: %zu samples at %u Hz -> %zu blocks (pitch %04Xh)\n", positional[1].c_str(), mono.size(),
              wav.sample_rate, blocks.size() / 16, static_cast<unsigned>((wav.sample_rate * 4096ull + 22050) / 44100));
  return 0;
}
