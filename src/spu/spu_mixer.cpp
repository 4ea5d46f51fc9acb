// SPU sample generation, once per 768 CPU cycles: key events, the 24 voices (pitch modulation,
// noise, envelopes, volumes), CD audio input with its volumes, the capture buffers in the first
// 4 KiB of sound RAM, reverb, the main volume, and the 44.1 kHz stereo output. The mix and the
// output are made only while something hears them (set_observed); the rest runs every sample.
#include <algorithm>
#include <bit>
#include <cstdlib>

#include "core/endian.h"
#include "spu/spu.h"

namespace psx {
namespace {

s32 clamp16(s32 v) { return std::clamp(v, -0x8000, 0x7FFF); }
s32 apply_volume(s32 sample, s32 volume) { return (sample * volume) >> 15; }

}  // namespace

void Spu::apply_key_events() {
  // KON/KOFF writes take effect at the next 44.1 kHz cycle (psx-spx "Unstable and Delayed I/O").
  if ((key_on_ | key_off_) == 0) return;
  for (u32 i = 0; i < kNumVoices; ++i) {
    const u32 bit = 1u << i;
    if (key_off_ & bit) voices_[i].key_off();
    if (key_on_ & bit) {
      voices_[i].key_on();
      endx_ &= ~bit;
    }
  }
  key_on_ = key_off_ = 0;
}

void Spu::sample_voice(u32 i, bool needed, Mix& mix) {
  spu::Voice& v = voices_[i];
  const u32 bit = 1u << i;
  v.fetch_block(ram_.data(), blocks_);
  // Every voice reads its block header and current sample each cycle, audible or not.
  check_irq(v.current_address() * 8u);
  check_irq(v.data_address());

  const bool noise = (noise_on_ & bit) != 0;
  if (needed) {
    // An envelope at 0 makes the product 0 whatever the sample: no interpolation then.
    const s32 level = v.adsr.level();
    const s32 sample = level == 0 ? 0 : noise ? noise_.level() : v.interpolate();
    v.output = static_cast<s16>(clamp16(apply_volume(sample, level)));
  }
  v.adsr.tick();

  // psx-spx "Pitch Counter": modulation by the previous voice's output, then clip to 4000h.
  u32 step = v.pitch;
  if (pitch_mod_ & bit) {
    const s32 factor = voices_[i - 1].output + 0x8000;
    step = static_cast<u32>((static_cast<s32>(static_cast<s16>(v.pitch)) * factor) >> 15) & 0xFFFF;
  }
  step = std::min<u32>(step, 0x4000);
  if (v.advance(step, noise) == spu::Voice::BlockEvent::LoopEnd) endx_ |= bit;

  if (needed && v.output != 0) {
    const s32 l = apply_volume(v.output, v.volume_left.level());
    const s32 r = apply_volume(v.output, v.volume_right.level());
    mix.left += l;
    mix.right += r;
    if (reverb_on_ & bit) {
      mix.reverb_left += l;
      mix.reverb_right += r;
    }
  }
  v.volume_left.tick();
  v.volume_right.tick();
}

void Spu::write_capture_buffers(StereoSample cd, s16 voice1, s16 voice3) {
  // psx-spx "SPU Memory layout": CD left/right before volume, voices 1 and 3 after the
  // envelope, 200h samples each. Capture IRQs need RAM_CTRL bits 2-3; the four halfwords lie in
  // four different 8-byte units, so the IRQ checks come before the writes in any order.
  const u32 off = capture_pos_ * 2;
  if ((ram_control_ & 0xC) != 0 && irq_possible()) {
    for (u32 b = 0; b < 4; ++b) check_irq(b * 0x400 + off);
  }
  u8* ram = ram_.data();
  store_le16(ram + off, static_cast<u16>(cd.left));
  store_le16(ram + 0x400 + off, static_cast<u16>(cd.right));
  store_le16(ram + 0x800 + off, static_cast<u16>(voice1));
  store_le16(ram + 0xC00 + off, static_cast<u16>(voice3));
  capture_pos_ = (capture_pos_ + 1) & 0x1FF;
}

u32 Spu::voices_needed() const {
  // Unobserved, a voice's output still matters where it reaches state, RAM or another voice:
  // voices 1 and 3 feed the capture buffers, a voice before one with PMON set modulates its
  // pitch, and reverb-enabled voices feed the reverb input history.
  if (mixing()) return (1u << kNumVoices) - 1;
  return (1u << 1) | (1u << 3) | (pitch_mod_ >> 1) | reverb_on_;
}

// push_output() and reverb_sample() run every sample and only this file calls them: inline.
inline void Spu::push_output(StereoSample out, u32 n) {
  // As n pushes one by one: the older half goes whenever a push finds the limit reached.
  for (u32 left = n; left > 0;) {
    if (output_.size() >= output_limit_) output_.erase(output_.begin(), output_.begin() + output_.size() / 2);
    const u32 now = static_cast<u32>(std::min<size_t>(left, output_limit_ - output_.size()));
    for (u32 k = 0; k < now; ++k) output_.push_back(out);
    left -= now;
  }
  if (capture_.active())
    for (u32 k = 0; k < n; ++k) capture_.push(out);
}

inline StereoSample Spu::reverb_sample(s32 in_left, s32 in_right, u32 later) {
  // The reverb unit always runs (its history and work area are state); its output is only
  // needed for a mix that hears it.
  if (reverb_unseen()) {
    reverb_.unseen_tick(in_left, in_right, later, ram_.data());
    return {};
  }
  // With the flag already up a hit changes nothing (raise_irq), so only a possible IRQ9 is watched.
  spu::Reverb::IrqWatch watch{irq_possible(), irq_address_, false};
  const StereoSample wet =
      reverb_.tick(in_left, in_right, ram_.data(), (attr_ & kAttrReverbEnable) != 0, reverb_heard(), watch);
  if (watch.hit) raise_irq();
  return wet;
}

void Spu::generate_sample(u32 skip, u32 later, bool reverb_made) {
  apply_key_events();
  Mix mix;
  const bool enabled = (attr_ & kAttrEnable) != 0;
  const bool mixing = this->mixing();
  if (enabled) {
    const u32 needed = voices_needed();
    // Lowest voice first (pitch modulation reads the previous voice's output of this sample).
    for (u32 left = ((1u << kNumVoices) - 1) & ~skip; left != 0; left &= left - 1) {
      const u32 i = static_cast<u32>(std::countr_zero(left));
      sample_voice(i, (needed >> i) & 1, mix);
    }
    noise_.tick(attr_);
  }
  // "Mute SPU" silences the voices; CD audio does not care.
  if (!(attr_ & kAttrUnmute)) mix.left = mix.right = 0;

  const StereoSample cd = cd_audio_.pop();
  write_capture_buffers(cd, capture_output(1, later), capture_output(3, later));
  const bool cd_reverb = (attr_ & kAttrCdReverb) != 0;
  if ((attr_ & kAttrCdEnable) && (mixing || cd_reverb)) {
    const s32 cd_left = apply_volume(cd.left, cd_volume_left_);
    const s32 cd_right = apply_volume(cd.right, cd_volume_right_);
    mix.left += cd_left;
    mix.right += cd_right;
    if (cd_reverb) {
      mix.reverb_left += cd_left;
      mix.reverb_right += cd_right;
    }
  }

  const StereoSample wet = reverb_made ? StereoSample{} : reverb_sample(mix.reverb_left, mix.reverb_right, later);
  if (mixing) {
    mix.left += apply_volume(wet.left, reverb_volume_left_);
    mix.right += apply_volume(wet.right, reverb_volume_right_);
    StereoSample out;
    out.left = static_cast<s16>(clamp16(apply_volume(clamp16(mix.left), main_left_.level())));
    out.right = static_cast<s16>(clamp16(apply_volume(clamp16(mix.right), main_right_.level())));
    if (output_taken()) push_output(out, 1);
    if (loud_threshold_ && (std::abs(out.left) > *loud_threshold_ || std::abs(out.right) > *loud_threshold_))
      loud_ = true;
  }
  main_left_.tick();
  main_right_.tick();
}

bool Spu::quiet_from_here(u32 skip) const {
  // Every voice stepped through the catch-up (step_unheard_voices: silent, unread because
  // nothing mixes, or read only by its capture buffer), no CD input, no IRQ9 possible (capture
  // and reverb checks) and no reverb output heard: each remaining sample's mix is 0 before and
  // after the main volume, or not made.
  constexpr u32 kAllVoices = (1u << kNumVoices) - 1;
  return skip == kAllVoices && cd_audio_.size() == 0 && !irq_possible() && !reverb_heard();
}

void Spu::quiet_samples(u32 n, bool reverb_made) {
  // What generate_sample() does for n samples when quiet_from_here() holds, stage by stage where
  // stages share nothing: the noise generator, the capture buffers (0 for the CD input; voices 1
  // and 3 as stepped: 0 where silent) with the reverb (input 0; its writes as ATTR says), the
  // output (0) and the main volume sweeps.
  if (attr_ & kAttrEnable)
    noise_.ticks(attr_, n);
  // Holds for the whole catch-up: tested once here rather than by reverb_sample() per sample.
  const bool unseen = reverb_unseen();
  if (reverb_made || (unseen && reverb_.quiet_ticks(n))) {
    // The reverb read none of the capture buffers: their writes may come after its ticks. Only
    // the last 200h samples' writes stay.
    const u32 count = std::min(n, 0x200u), start = (capture_pos_ + n - count) & 0x1FF;
    for (u32 buffer = 0; buffer < 4; ++buffer) {
      const s16* out = buffer >= 2 ? captured_tail(2 * buffer - 3, count) : nullptr;  // voices 1, 3
      u8* ram = ram_.data() + buffer * 0x400;
      // Up to the buffer's end, then from its start.
      for (u32 from = 0, pos = start; from < count; pos = 0) {
        const u32 run = std::min(count - from, 0x200 - pos);
        if (out) {
          for (u32 k = 0; k < run; ++k) store_le16(ram + (pos + k) * 2, static_cast<u16>(out[from + k]));
        } else {
          std::fill_n(ram + pos * 2, run * 2, u8{0});  // CD input, silent voices
        }
        from += run;
      }
    }
    capture_pos_ = (capture_pos_ + n) & 0x1FF;
  } else {
    for (u32 k = 0; k < n; ++k) {
      // Sample by sample: the reverb may read the capture buffers, or write them.
      const u32 off = capture_pos_ * 2, later = n - 1 - k;
      store_le16(ram_.data() + off, 0);
      store_le16(ram_.data() + 0x400 + off, 0);
      store_le16(ram_.data() + 0x800 + off, static_cast<u16>(capture_output(1, later)));
      store_le16(ram_.data() + 0xC00 + off, static_cast<u16>(capture_output(3, later)));
      capture_pos_ = (capture_pos_ + 1) & 0x1FF;
      if (unseen) reverb_.unseen_tick(0, 0, n - 1 - k, ram_.data());
      else reverb_sample(0, 0, n - 1 - k);
    }
  }
  if (output_taken()) push_output({}, n);
  if (!main_left_.latched()) main_left_.ticks(n);
  if (!main_right_.latched()) main_right_.ticks(n);
}

void Spu::do_state(StateIO& s) {
  // A saved state holds every sample due by now; a load makes none (the scheduler's time is
  // already the loaded one, and the samples due before it belong to the abandoned timeline).
  if (!s.loading()) sync();
  // Version 2 keeps only the outputs of voices 1 and 3 (Voice::output); version 1 saved all.
  // Version 3 adds the cycles to the next sample.
  const u32 version = s.section("SPU ", 3, 1);
  s.bytes(ram_.data(), ram_.size());
  for (spu::Voice& v : voices_) v.do_state(s, version < 2);
  if (version >= 2) {
    s.pod(voices_[1].output);
    s.pod(voices_[3].output);
  }
  reverb_.do_state(s, ram_.data());
  noise_.do_state(s);
  main_left_.do_state(s);
  main_right_.do_state(s);
  s.pod(cd_volume_left_);
  s.pod(cd_volume_right_);
  s.pod(ext_volume_left_);
  s.pod(ext_volume_right_);
  s.pod(reverb_volume_left_);
  s.pod(reverb_volume_right_);
  s.pod(key_on_);
  s.pod(key_off_);
  s.pod(pitch_mod_);
  s.pod(noise_on_);
  s.pod(reverb_on_);
  s.pod(endx_);
  s.pod(attr_);
  s.boolean(irq_flag_);
  s.pod(irq_address_);
  s.pod(transfer_start_);
  s.pod(transfer_addr_);
  s.pod(ram_control_);
  s.pod(fifo_);
  s.pod(fifo_count_);
  s.pod(capture_pos_);
  s.pod(raw_);
  if (s.loading() && (fifo_count_ > kFifoSize || capture_pos_ > 0x1FF || transfer_addr_ >= kRamSize))
    s.fail("SPU transfer state out of range");
  next_sample_state(s, version);
  s.end_section("SPU ");
  if (s.loading()) book();  // the loaded ATTR and capture position decide the booking
}

void Spu::next_sample_state(StateIO& s, u32 version) {
  // Relative to the scheduler's time, which a console loads first; a standalone SPU loaded on
  // another timeline keeps the distance to its next sample.
  if (version < 3) {
    // Earlier builds booked the SPU's event at every sample: the loaded booking is the next one.
    next_sample_ = sched_.pending(sample_event_) ? sched_.when(sample_event_) : sched_.now() + kCyclesPerSample;
    return;
  }
  Cycles ahead = next_sample_ - sched_.now();
  s.pod(ahead);
  if (s.loading() && (ahead == 0 || ahead > kCyclesPerSample)) s.fail("SPU next sample out of range");
  next_sample_ = sched_.now() + ahead;
}

}  // namespace psx
