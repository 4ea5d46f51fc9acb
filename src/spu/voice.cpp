// SPU voice playback: ADPCM block fetching with loop flags, pitch counter, interpolation
// (psx-spx "SPU ADPCM Samples", "SPU ADPCM Pitch", "4-Point Gaussian Interpolation").
#include "spu/voice.h"

#include <algorithm>

#include "spu/gauss.h"

namespace psx::spu {

void Voice::key_on() {
  current_address_ = start_address & ~1u;  // blocks are 16 bytes
  counter_ = 0;
  has_block_ = false;
  ignore_loop_start_ = false;
  history_ = {};
  // The interpolation must not reach back into the previous sound.
  std::fill(samples_.begin(), samples_.end(), 0);
  adsr.key_on();
}

void Voice::write_repeat_address(u16 value) {
  repeat_address = value;
  if (adsr.phase() != Adsr::Phase::Off) ignore_loop_start_ = true;
}

void Voice::fetch_block(const u8* ram, AdpcmBlockCache& blocks) {
  if (has_block_) return;
  const u32 address = (current_address_ * 8u) & 0x7FFFF;
  const AdpcmBlockCache::Decoded& d = blocks.decode(ram, address, history_);
  std::copy(d.samples.begin(), d.samples.end(), samples_.begin() + 3);
  history_ = d.history;
  block_flags_ = ram[address + 1];
  has_block_ = true;
  if ((block_flags_ & kAdpcmLoopStart) && !ignore_loop_start_) repeat_address = current_address_;
}

s32 Voice::interpolate() const {
  const u32 s = counter_ >> 12;
  const u32 i = (counter_ >> 4) & 0xFF;
  return gauss_interpolate(samples_[s], samples_[s + 1], samples_[s + 2], samples_[s + 3], i);
}

Voice::BlockEvent Voice::advance(u32 step, bool noise) {
  counter_ += step;
  if ((counter_ >> 12) < kAdpcmBlockSamples) return BlockEvent::None;
  counter_ -= kAdpcmBlockSamples << 12;
  // Keep the last three samples for interpolation across the block boundary.
  std::copy(samples_.end() - 3, samples_.end(), samples_.begin());
  has_block_ = false;
  if (!(block_flags_ & kAdpcmLoopEnd)) {
    current_address_ += 2;
    return BlockEvent::NextBlock;
  }
  current_address_ = repeat_address & ~1u;
  if (!(block_flags_ & kAdpcmLoopRepeat) && !noise) adsr.force_off();
  return BlockEvent::LoopEnd;
}

bool Voice::step_unheard(const u8* ram, AdpcmBlockCache& blocks, u32 step, bool noise, u32 samples,
                         RamWindow unwritten, bool& loop_end) {
  // psx-spx "SPU ADPCM Pitch": the counter moves by `step` each sample and a block is left when
  // bits 12+ reach 28, so the crossings fall every ceil(remaining / step) samples.
  constexpr u32 kBlockEnd = kAdpcmBlockSamples << 12;
  const bool ticking = !silent();
  const auto tick = [&](u32 n) {
    if (!ticking) return;
    adsr.ticks(n);
    if (!volume_left.latched()) volume_left.ticks(n);
    if (!volume_right.latched()) volume_right.ticks(n);
  };
  u32 done = 0;  // samples stepped so far
  while (true) {
    const u32 left = samples - done;
    const u32 to_cross = step == 0 ? left + 1 : (kBlockEnd - counter_ + step - 1) / step;
    if (!has_block_) {
      const u32 addr = (current_address_ * 8u) & 0x7FFFF;
      // The first read sees the RAM of the run's first sample; later ones must not be written.
      if (done > 0 && (addr < unwritten.begin || addr + kAdpcmBlockBytes > unwritten.end)) return false;
      fetch_block(ram, blocks);
    }
    if (to_cross > left) {
      tick(left);
      counter_ += left * step;  // stays inside the block
      return true;
    }
    // The envelope ticks of these samples come before the crossing's End+Mute (advance()).
    tick(to_cross);
    // counter_ + to_cross * step < kBlockEnd + step: advance() leaves the block exactly once.
    if (advance(to_cross * step, noise) == BlockEvent::LoopEnd) loop_end = true;
    done += to_cross;
    if (done == samples) return true;
  }
}

bool Voice::step_captured(const u8* ram, AdpcmBlockCache& blocks, u32 step, u32 samples, RamWindow unwritten,
                          s16* out, bool& loop_end) {
  // Spu::sample_voice() for a needed voice without noise, IRQ checks or mix.
  for (u32 k = 0; k < samples; ++k) {
    if (!has_block_) {
      const u32 addr = (current_address_ * 8u) & 0x7FFFF;
      if (k > 0 && (addr < unwritten.begin || addr + kAdpcmBlockBytes > unwritten.end)) return false;
      fetch_block(ram, blocks);
    }
    const s32 level = adsr.level();
    out[k] = level == 0 ? 0 : static_cast<s16>(std::clamp((interpolate() * level) >> 15, -0x8000, 0x7FFF));
    adsr.tick();
    if (advance(step, false) == BlockEvent::LoopEnd) loop_end = true;
    volume_left.tick();
    volume_right.tick();
  }
  output = out[samples - 1];
  return true;
}

void Voice::do_state(StateIO& s, bool with_output) {
  volume_left.do_state(s);
  volume_right.do_state(s);
  s.pod(pitch);
  s.pod(start_address);
  adsr.do_state(s);
  s.pod(repeat_address);
  if (with_output) s.pod(output);
  s.pod(current_address_);
  s.pod(counter_);
  s.boolean(has_block_);
  s.boolean(ignore_loop_start_);
  s.pod(block_flags_);
  s.pod(history_);
  s.pod(samples_);
  if (s.loading() && (counter_ >> 12) >= kAdpcmBlockSamples) s.fail("voice pitch counter out of range");
}

}  // namespace psx::spu
