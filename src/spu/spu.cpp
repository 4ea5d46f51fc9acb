// When the SPU makes its samples: lazily, in batches, with the scheduler event booked only where a
// sample could be seen without anything asking (spu.h). Every observer syncs first, so each
// sample is made exactly as an event at every sample would have made it.
#include <algorithm>

#include "spu/spu.h"

namespace psx {

Spu::Spu(Scheduler& sched, InterruptController& irq, AudioFifo& cd_audio)
    : sched_(sched), irq_(irq), cd_audio_(cd_audio), ram_(kRamSize, 0) {
  sample_event_ = sched_.add_event("spu.sample", [this](Cycles) { on_sample(); });
  next_sample_ = sched_.now() + kCyclesPerSample;
  cd_audio_.before_push = [this] { sync(); };
  book();
}

void Spu::catch_up(Cycles horizon) {
  const u32 due = static_cast<u32>((horizon - next_sample_) / kCyclesPerSample) + 1;
  // The first sample applies the pending key events; from the second on no register changes
  // until the catch-up ends, so voices nothing reads can step through the rest at once. The
  // reference (max batch 1) makes every sample in full.
  const bool reference = max_batch_ <= 1;
  // An unseen reverb that nothing feeds takes nothing from the samples: all its ticks at once,
  // where none of them reads a capture buffer (Reverb::quiet_ticks).
  const bool reverb_made = !reference && reverb_unfed() && reverb_unseen() && reverb_.quiet_ticks(due);
  captured_ = 0;
  u32 skip = 0;
  for (u32 k = 0; k < due; ++k) {
    if (k > 0 && !reference && quiet_from_here(skip)) {
      quiet_samples(due - k, reverb_made);
      next_sample_ += (due - k) * kCyclesPerSample;
      return;
    }
    const bool mixed = mixing();
    generate_sample(skip, reference ? 0 : due - 1 - k, reverb_made);
    next_sample_ += kCyclesPerSample;
    // Voices nothing reads step through the rest at once: from the second sample on, and again
    // where a loud sample ends a loudness watch's mix (no voice is read for the mix from then).
    if (!reference && k + 1 < due && (k == 0 || (mixed && !mixing())))
      skip |= step_unheard_voices(due - 1 - k, skip);
  }
}

u32 Spu::step_unheard_voices(u32 samples, u32 stepped) {
  // A voice nothing reads (voices_needed) is its pitch counter, its block fetches, its envelope
  // and its volume sweeps; a silent one (Voice::silent: output 0, so it may be needed) only the
  // first two; voice 1 or 3 read only by its capture buffer also its output, kept for the
  // buffer's writes (capture_output). Not with IRQ9 possible (every block header and sample read is
  // checked against IRQA), not while the voices do not run (SPU disabled).
  if (!(attr_ & kAttrEnable) || irq_possible()) return 0;
  // The SPU writes the capture buffers (0..FFFh) every sample and, with ATTR bit 7, the reverb
  // work area (ESA*8..7FFFFh, psx-spx "SPU Reverb Registers").
  const spu::Voice::RamWindow unwritten{0x1000, (attr_ & kAttrReverbEnable) ? reverb_.base() * 8u : kRamSize};
  const u32 needed = voices_needed();
  for (u32 i = 0; i < kNumVoices; ++i) {
    spu::Voice& v = voices_[i];
    const u32 bit = 1u << i;
    const bool capture = (needed & bit) && !v.silent();
    if ((stepped & bit) || (capture && !(captured_only() & bit))) continue;
    // psx-spx "Pitch Counter": modulation by a silent voice (output 0) leaves the pitch as is.
    if ((pitch_mod_ & bit) && !voices_[i - 1].silent()) continue;
    const spu::Voice before = v;
    const u32 step = std::min<u32>(v.pitch, 0x4000);
    bool loop_end = false;
    const bool stepped_all =
        capture ? v.step_captured(ram_.data(), blocks_, step, samples, unwritten, captured_buffer(i, samples), loop_end)
                : v.step_unheard(ram_.data(), blocks_, step, (noise_on_ & bit) != 0, samples, unwritten, loop_end);
    if (!stepped_all) {
      v = before;
      continue;
    }
    if (loop_end) endx_ |= bit;
    if (capture) captured_ |= bit;
    else if (needed & bit) v.output = 0;
    stepped |= bit;
  }
  return stepped;
}

u32 Spu::captured_only() const {
  // Voices 1 and 3 feed their capture buffers; nothing else reads them while nothing mixes, they
  // modulate no pitch and feed no reverb. Without noise their outputs depend on nothing else in
  // the SPU (step_unheard_voices lets only a silent voice modulate their pitch).
  constexpr u32 kCaptureVoices = (1u << 1) | (1u << 3);
  if (mixing()) return 0;
  return kCaptureVoices & ~((pitch_mod_ >> 1) | reverb_on_ | noise_on_);
}

s16* Spu::captured_buffer(u32 voice, u32 samples) {
  std::vector<s16>& out = captured_out_[voice / 2];
  out.resize(samples);
  captured_samples_ = samples;
  return out.data();
}

void Spu::on_sample() {
  sync();
  book();
}

Cycles Spu::next_booking() const {
  // A sample that could raise IRQ9 has to run at its own time (the CPU takes the interrupt at the
  // next instruction), so then every sample is booked.
  if (max_batch_ <= 1 || irq_possible()) return next_sample_;
  // SPUSTAT bit 11 (capture_pos_ >= 100h) flips with the sample that writes position FFh or
  // 1FFh: where the batch ends there, a SPUSTAT read between events sees no change.
  u32 batch = max_batch_;
  if (batches_end_at_flips_) batch = std::min(batch, 0x100 - (capture_pos_ & 0xFF));
  return next_sample_ + (batch - 1) * kCyclesPerSample;
}

bool Spu::end_batches_at_flips() {
  if (batches_end_at_flips_) return false;
  sync();
  batches_end_at_flips_ = true;
  book();
  return true;
}

void Spu::book() {
  const Cycles when = next_booking();
  const Cycles booked = sched_.when(sample_event_);
  if (when == booked) return;
  // Moving a booking later needs the scheduler's deadline recomputed, or the CPU would stop at
  // the old one for nothing.
  if (booked != Scheduler::kNever && when > booked) sched_.cancel(sample_event_);
  sched_.schedule_at(sample_event_, when);
}

void Spu::set_max_batch(u32 samples) {
  sync();
  max_batch_ = std::max(samples, 1u);
  book();
}

void Spu::sync_for_state() {
  sync();
  if (sched_.when(sample_event_) != next_sample_) {
    sched_.cancel(sample_event_);
    sched_.schedule_at(sample_event_, next_sample_);
  }
}

void Spu::take_samples(std::vector<StereoSample>& out) {
  sync();
  out.clear();
  out.swap(output_);
}

}  // namespace psx
