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
  while (next_sample_ <= horizon) {
    generate_sample();
    next_sample_ += kCyclesPerSample;
  }
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
  // 1FFh: the batch ends there, so a SPUSTAT read between events sees no change (idle skipping
  // relies on that).
  const u32 to_flip = 0x100 - (capture_pos_ & 0xFF);
  const u32 batch = std::min(max_batch_, to_flip);
  return next_sample_ + (batch - 1) * kCyclesPerSample;
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
