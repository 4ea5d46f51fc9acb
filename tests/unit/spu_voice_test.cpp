// SPU voices through the register interface: Gaussian interpolation (psx-spx table values),
// a looped ADPCM sine played at a chosen pitch (frequency from a DFT peak, level from the
// volumes), loop flags with ENDX and LSAX, pitch modulation, and save-state round trips.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "spu/adpcm.h"
#include "spu/gauss.h"
#include "spu_test_util.h"

using namespace psx;
using namespace psx::spu;
using psx::test::SpuRig;

namespace {

// Envelope used for steady tones: attack shift 0 (+14336 per sample: 7FFFh after 3 samples),
// sustain level 15 = 8000h, which 7FFFh already satisfies, so decay ends on its first sample
// before any step; sustain rate 7Fh never steps: the level stays 32767.
constexpr u16 kAdsr1 = 0x00FF;
constexpr u16 kAdsr2 = 0x1FC0;

void setup_voice(SpuRig& r, u32 v, u32 byte_addr, u16 pitch) {
  r.voice_w(v, 0x0, 0x3FFF);  // VOLL: fixed 7FFEh
  r.voice_w(v, 0x2, 0x3FFF);  // VOLR
  r.voice_w(v, 0x4, pitch);
  r.voice_w(v, 0x6, static_cast<u16>(byte_addr / 8));
  r.voice_w(v, 0x8, kAdsr1);
  r.voice_w(v, 0xA, kAdsr2);
}

void key_on(SpuRig& r, u32 mask) {
  r.w16(0x1F801D88, static_cast<u16>(mask));
  r.w16(0x1F801D8A, static_cast<u16>(mask >> 16));
}

std::vector<u8> silent_blocks(u32 n, u8 first_flags, u8 last_flags) {
  std::vector<u8> b(n * 16, 0);
  b[1] |= first_flags;
  b[(n - 1) * 16 + 1] |= last_flags;
  return b;
}

}  // namespace

TEST(SpuGauss, TableMatchesPsxSpx) {
  // Spot values from the psx-spx table and its documented property: the four weights used
  // together sum to 7F7Fh..7F81h.
  EXPECT_EQ(kGaussTable[0x000], -1);
  EXPECT_EQ(kGaussTable[0x0FF], 0x12C7);
  EXPECT_EQ(kGaussTable[0x100], 0x1307);
  EXPECT_EQ(kGaussTable[0x1FF], 0x59B3);
  for (u32 i = 0; i < 256; ++i) {
    s32 sum = kGaussTable[i] + kGaussTable[0xFF - i] + kGaussTable[0x100 + i] + kGaussTable[0x1FF - i];
    EXPECT_GE(sum, 0x7F7F) << i;
    EXPECT_LE(sum, 0x7F81) << i;
  }
}

TEST(SpuGauss, InterpolationByHand) {
  // i = 0: 12C7h*1000>>15 = 146, 59B3h*2000>>15 = 1401, 1307h*3000>>15 = 445, -1*4000>>15 = -1.
  EXPECT_EQ(gauss_interpolate(1000, 2000, 3000, 4000, 0), 146 + 1401 + 445 - 1);
  // i = 80h on a constant 10000: g[7Fh]=19Ch -> 125, g[17Fh]=3DEFh -> 4838, g[180h]=3E4Ch ->
  // 4866, g[80h]=1A8h -> 129.
  EXPECT_EQ(gauss_interpolate(10000, 10000, 10000, 10000, 0x80), 125 + 4838 + 4866 + 129);
}

TEST(SpuVoice, SinePlaysAtPitchFrequencyAndLevel) {
  SpuRig r;
  // A sine of period 32 samples, 896 samples long (whole periods and whole blocks), looped.
  const double amplitude = 16000;
  std::vector<s16> pcm(896);
  for (size_t i = 0; i < pcm.size(); ++i) pcm[i] = static_cast<s16>(std::lround(amplitude * std::sin(2 * M_PI * i / 32)));
  AdpcmEncodeOptions loop;
  loop.loop = true;
  r.put_ram(0x1000, encode_adpcm(pcm.data(), pcm.size(), loop));

  r.w16(0x1F801DAA, 0xC000);  // ATTR: SPU enable, unmute
  r.w16(0x1F801D80, 0x3FFF);  // MVOLL/MVOLR: 7FFEh
  r.w16(0x1F801D82, 0x3FFF);
  // Pitch 0800h = 22.05 kHz: the 32-sample period lasts 64 output samples (689.06 Hz).
  setup_voice(r, 0, 0x1000, 0x0800);
  key_on(r, 1);
  r.run_samples(300);
  r.take();
  const size_t n = 4096;
  r.run_samples(n);
  auto out = r.take();
  ASSERT_EQ(out.size(), n);

  // Straight DFT of the left channel over bins 1..256: the peak must be bin 4096/64 = 64.
  size_t peak = 0;
  double peak_amp = 0;
  for (size_t k = 1; k <= 256; ++k) {
    std::complex<double> acc = 0;
    for (size_t t = 0; t < n; ++t) acc += double(out[t].left) * std::polar(1.0, -2 * M_PI * double(k * t) / n);
    const double amp = 2 * std::abs(acc) / n;
    if (amp > peak_amp) peak_amp = amp, peak = k;
  }
  EXPECT_EQ(peak, 64u);
  // Level: 16000 * ENVX 32767/32768 * VOL 32766/32768 * MVOL 32766/32768 = 15998; allow 4%
  // for ADPCM quantisation and the interpolator's slight low-pass.
  EXPECT_NEAR(peak_amp, 15998, 15998 * 0.04);
  for (size_t t = 0; t < n; ++t) ASSERT_EQ(out[t].left, out[t].right) << t;
  EXPECT_EQ(r.voice_r(0, 0xC), 32767);  // ENVX
}

TEST(SpuVoice, LoopFlagsEndxAndRepeatAddress) {
  SpuRig r;
  r.w16(0x1F801DAA, 0xC000);
  // Voice 2: three blocks, the last End+Mute. Voice 3: two blocks, LoopStart then End+Repeat.
  r.put_ram(0x2000, silent_blocks(3, 0, kAdpcmLoopEnd));
  r.put_ram(0x3000, silent_blocks(2, kAdpcmLoopStart, kAdpcmLoopEnd | kAdpcmLoopRepeat));
  setup_voice(r, 2, 0x2000, 0x1000);
  setup_voice(r, 3, 0x3000, 0x1000);
  key_on(r, 0b1100);
  // At pitch 1000h a voice moves one sample per output sample: block ends after 28, 56, 84.
  r.run_samples(55);
  EXPECT_EQ(r.r16(0x1F801D9C), 0);
  EXPECT_EQ(r.voice_r(3, 0xE), 0x3000 / 8);  // LSAX took the LoopStart block's address
  r.run_samples(1);
  EXPECT_EQ(r.r16(0x1F801D9C), 1 << 3);
  EXPECT_NE(r.voice_r(3, 0xC), 0);  // End+Repeat keeps playing
  r.run_samples(27);
  EXPECT_EQ(r.r16(0x1F801D9C), 1 << 3);
  EXPECT_NE(r.voice_r(2, 0xC), 0);
  r.run_samples(1);
  EXPECT_EQ(r.r16(0x1F801D9C), (1 << 3) | (1 << 2));
  EXPECT_EQ(r.voice_r(2, 0xC), 0);  // End+Mute: ENVX forced to 0
  // Key on clears the voice's ENDX bit (applied on the next sample).
  key_on(r, 0b100);
  r.run_samples(1);
  EXPECT_EQ(r.r16(0x1F801D9C), 1 << 3);
  // A write to LSAX while playing wins over the LoopStart flag.
  r.voice_w(3, 0xE, 0x3000 / 8 + 2);
  r.run_samples(28 * 3);
  EXPECT_EQ(r.voice_r(3, 0xE), 0x3000 / 8 + 2);
}

TEST(SpuVoice, RamIrqWhenAVoiceReadsTheIrqAddress) {
  SpuRig r;
  r.put_ram(0x3000, silent_blocks(2, kAdpcmLoopStart, kAdpcmLoopEnd | kAdpcmLoopRepeat));
  setup_voice(r, 3, 0x3000, 0x1000);
  r.w16(0x1F801DA4, 0x3010 / 8);  // IRQA: the second block
  r.w16(0x1F801DAA, 0xC040);      // enable, unmute, IRQ9 enable
  key_on(r, 1 << 3);
  r.run_samples(28);
  EXPECT_EQ(r.irq.stat() & (1 << 9), 0u);
  EXPECT_EQ(r.r16(0x1F801DAE) & 0x40, 0);
  r.run_samples(1);  // sample 29 reads the second block's header
  EXPECT_EQ(r.irq.stat() & (1 << 9), 1u << 9);
  EXPECT_EQ(r.r16(0x1F801DAE) & 0x40, 0x40);
  r.w16(0x1F801DAA, 0xC000);  // acknowledge
  EXPECT_EQ(r.r16(0x1F801DAE) & 0x40, 0);
}

TEST(SpuVoice, PitchModulationByThePreviousVoice) {
  SpuRig r;
  r.w16(0x1F801DAA, 0xC000);
  // Voice 0 plays a constant 16384 (filter 0, shift 0, nibbles 4: 4 << 12), looped; its output
  // once the history is full: 12C7h*16384>>15 + 59B3h*16384>>15 + 1307h*16384>>15 + (-1*16384>>15)
  // = 2403 + 11481 + 2435 - 1 = 16318, times ENVX 32767 >> 15 = 16317.
  std::vector<u8> dc(16, 0x44);
  dc[0] = 0x00;
  dc[1] = kAdpcmLoopStart | kAdpcmLoopEnd | kAdpcmLoopRepeat;
  r.put_ram(0x1000, dc);
  r.put_ram(0x4000, silent_blocks(400, kAdpcmLoopStart, kAdpcmLoopEnd | kAdpcmLoopRepeat));
  setup_voice(r, 0, 0x1000, 0x1000);
  setup_voice(r, 1, 0x4000, 0x1000);
  r.w16(0x1F801D90, 1 << 1);  // PMON: voice 1 modulated by voice 0
  key_on(r, 0b11);
  r.run_samples(40);
  // Step = 1000h * (16317 + 8000h) >> 15 = 4096 * 49085 >> 15 = 6135 per sample.
  const u16 a0 = r.spu.voice(1).current_address();
  r.run_samples(2800);
  const u32 blocks = (r.spu.voice(1).current_address() - a0) / 2;
  // 2800 * 6135 / (28 * 4096) = 149.8 blocks (unmodulated it would be 97.7).
  EXPECT_GE(blocks, 149u);
  EXPECT_LE(blocks, 150u);
}

TEST(SpuVoice, SaveStateRoundTripGivesTheSameFuture) {
  SpuRig r;
  std::vector<s16> pcm(560);
  for (size_t i = 0; i < pcm.size(); ++i) pcm[i] = static_cast<s16>(9000 * std::sin(2 * M_PI * i / 40.0));
  AdpcmEncodeOptions loop;
  loop.loop = true;
  r.put_ram(0x1000, encode_adpcm(pcm.data(), pcm.size(), loop));
  r.w16(0x1F801DAA, 0xC080);  // reverb writes on too
  r.w16(0x1F801D80, 0x3FFF);
  r.w16(0x1F801D82, 0x3FFF);
  r.w16(0x1F801D84, 0x2000);  // EVOLL/EVOLR
  r.w16(0x1F801D86, 0x2000);
  r.w16(0x1F801DA2, 0xE000);  // ESA
  const u16 studio_small[32] = {0x0033, 0x0025, 0x70F0, 0x4FA8, 0xBCE0, 0x4410, 0xC0F0, 0x9C00,
                                0x5280, 0x4EC0, 0x03E4, 0x031B, 0x03A4, 0x02AF, 0x0372, 0x0266,
                                0x031C, 0x025D, 0x025C, 0x018E, 0x022F, 0x0135, 0x01D2, 0x00B7,
                                0x018F, 0x00B5, 0x00B4, 0x0080, 0x004C, 0x0026, 0x8000, 0x8000};
  for (u32 i = 0; i < 32; ++i) r.w16(0x1F801DC0 + 2 * i, studio_small[i]);
  r.w16(0x1F801D98, 1);  // EON voice 0
  setup_voice(r, 0, 0x1000, 0x0C00);
  key_on(r, 1);
  r.run_samples(3000);

  StateIO w;
  r.sched.do_state(w);
  r.spu.do_state(w);
  const std::vector<u8> blob = w.buffer();
  r.take();
  r.run_samples(2000);
  auto first = r.take();

  StateIO rd(blob.data(), blob.size());
  r.sched.do_state(rd);
  r.spu.do_state(rd);
  EXPECT_TRUE(rd.at_end());
  r.run_samples(2000);
  auto second = r.take();
  ASSERT_EQ(first.size(), second.size());
  bool any_sound = false;
  for (size_t i = 0; i < first.size(); ++i) {
    ASSERT_EQ(first[i].left, second[i].left) << i;
    ASSERT_EQ(first[i].right, second[i].right) << i;
    any_sound |= first[i].left != 0;
  }
  EXPECT_TRUE(any_sound);
  // A truncated blob is refused with an error, not a crash.
  StateIO bad(blob.data(), blob.size() / 2);
  r.sched.do_state(bad);
  EXPECT_THROW(r.spu.do_state(bad), StateError);
}
