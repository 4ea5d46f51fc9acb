// The Sound Processing Unit (psx-spx "Sound Processing Unit (SPU)"): registers at 1F801C00h
// (400h bytes), 512 KiB of sound RAM filled by manual writes or DMA channel 4, 24 ADPCM voices,
// reverb, CD audio input, and stereo 16-bit output at 44.1 kHz - one sample every 768 CPU
// cycles. The samples are made lazily, in batches: whatever can observe the SPU (its registers,
// DMA, CD audio pushes, the output, save states) first makes every sample due by then, each
// exactly as at its own time, and the SPU's scheduler event is booked only where a sample could
// do something visible by itself (an IRQ, a SPUSTAT change) or a batch ends. The console and
// environment take the produced samples and control audio capture through the public API below.
#pragma once
#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "core/audio_fifo.h"
#include "core/io_device.h"
#include "core/irq.h"
#include "core/scheduler.h"
#include "core/state.h"
#include "core/types.h"
#include "spu/capture.h"
#include "spu/noise.h"
#include "spu/reverb.h"
#include "spu/voice.h"

namespace psx {

class Spu final : public IoDevice, public DmaPort {
 public:
  static constexpr u32 kBase = 0x1F801C00;
  static constexpr u32 kSize = 0x400;
  static constexpr u32 kRamSize = spu::kSoundRamBytes;
  static constexpr u32 kNumVoices = 24;
  static constexpr u32 kSampleRate = 44100;
  static constexpr Cycles kCyclesPerSample = 768;  // 33.8688 MHz / 44.1 kHz
  // Longest batch, in samples: several frames (5.6 at 60 Hz). Each event ends an idle skip and
  // each catch-up has a fixed cost. An observer's catch-up (an environment's per-frame
  // take_loud()) does not move the event booked at the batch's start, so the event runs once per
  // this many samples: at 1024, Tumble's environment made 2.3 catch-ups a frame; at 4096, 1.3.
  static constexpr u32 kDefaultMaxBatch = 4096;

  Spu(Scheduler& sched, InterruptController& irq, AudioFifo& cd_audio);

  // --- Lazy sample generation ---------------------------------------------------------------
  // Makes every sample due by now (inside an event's callback: by that event's turn, as if the
  // SPU's event were booked at every sample, Scheduler::horizon). Everything public below that
  // observes the SPU calls it first.
  void sync() {
    const Cycles horizon = sched_.horizon(sample_event_);
    if (next_sample_ <= horizon) catch_up(horizon);
  }
  // The most samples one event may make (1: an event at every sample, the reference schedule;
  // results are bit-identical for any value).
  void set_max_batch(u32 samples);
  u32 max_batch() const { return max_batch_; }
  // SPUSTAT bit 11 flips every 256 samples (the capture buffers' halves, psx-spx "SPU Status
  // Register"), between events unless a batch ends at each flip. Idle skipping counts on an I/O
  // register it lets a loop poll changing only at events (cpu/idle_skip.h), so it calls this when
  // it meets a loop reading SPUSTAT: from then on batches end at the flips. Returns whether that
  // was new (the event may then come sooner than the skipper saw). Results are the same bits
  // either way, as for any batching.
  bool end_batches_at_flips();
  // Makes the samples due and books the SPU's event at its next sample, whatever the batching, so
  // that a save state made now is the same bytes either way; the console calls it before saving
  // (loading do_state() books the event again by the loaded registers).
  void sync_for_state();

  u32 io_read(u32 offset, u32 width) override;
  void io_write(u32 offset, u32 value, u32 width) override;

  // DMA channel 4 (psx-spx "SPU RAM DMA-Write/Read"): words go to/from the transfer address.
  void dma_write(const u32* words, u32 count) override;
  void dma_read(u32* words, u32 count) override;
  bool dma_request() const override;
  Cycles dma_block_cycles(u32 words) const override;

  // --- Output ----------------------------------------------------------------------------
  // Moves the samples produced since the last call into `out` (cleared first; the two vectors
  // swap storage, so nothing is copied).
  void take_samples(std::vector<StereoSample>& out);
  size_t pending_samples() {
    sync();
    return output_.size();
  }
  // Bounds the untaken output so a console nobody listens to does not grow without end: when
  // the limit is reached the older half is dropped. Default one minute; SIZE_MAX keeps all.
  void set_output_limit(size_t samples) {
    sync();
    output_limit_ = samples < 2 ? 2 : samples;
  }
  // Whether anything takes the output samples (on at power-on). Off, the SPU still advances
  // voices, envelopes, sweeps, noise, reverb, the capture buffers, ENDX and the IRQ address
  // checks exactly, but skips the final mix, the reverb output filter, the interpolation of
  // voices whose output reaches nothing else and, while the reverb neither writes its work area
  // nor could raise IRQ9, its values until its output could be heard (Reverb::owe_tick), and
  // produces no output samples. A running capture keeps the output mixed.
  void set_observed(bool observed) {
    sync();
    observed_ = observed;
  }
  bool observed() const { return observed_; }
  // A listener that needs only to know whether the output got loud (a move delimiter waiting
  // for silence) sets a threshold instead of observing: the SPU then mixes each sample only until
  // one has a channel beyond the threshold in magnitude since the last take_loud(), and the rest
  // as unheard; no output samples are made for it. Empty: no such listener.
  void watch_loudness(std::optional<u16> threshold) {
    sync();
    loud_threshold_ = threshold;
    loud_ = false;
  }
  // Whether a sample made since the last call was loud (the mix as observed would have made it).
  bool take_loud() {
    sync();
    return std::exchange(loud_, false);
  }
  std::optional<u16> loudness_threshold() const { return loud_threshold_; }

  // --- Capture (seed §2.5) ----------------------------------------------------------------
  void start_capture(const spu::CaptureOptions& options) {
    sync();
    capture_.start(options);
  }
  // Stops the recording and returns it, cropped.
  std::vector<StereoSample> stop_capture() {
    sync();
    return capture_.stop();
  }
  const spu::AudioCapture& capture() {
    sync();
    return capture_;
  }

  // Sound RAM, for tests and tools (who may write it: owed reverb values are made first).
  u8* ram() {
    sync();
    reverb_.settle(ram_.data());
    return ram_.data();
  }
  const spu::Voice& voice(u32 i) {
    sync();
    return voices_[i];
  }

  // Save states hold the whole SPU; the not-yet-taken output samples and a running capture
  // are the host's, not the console's, and are not part of the state.
  void do_state(StateIO& s);

 private:
  // Register offsets (from 1F801C00h) of the control block, names from psx-spx.
  enum : u32 {
    kMVOLL = 0x180, kMVOLR = 0x182, kEVOLL = 0x184, kEVOLR = 0x186,
    kKON = 0x188, kKOFF = 0x18C, kPMON = 0x190, kNON = 0x194, kEON = 0x198, kENDX = 0x19C,
    kESA = 0x1A2, kIRQA = 0x1A4, kTSA = 0x1A6, kFIFO = 0x1A8, kATTR = 0x1AA, kRAMCTRL = 0x1AC,
    kSTAT = 0x1AE, kAVOLL = 0x1B0, kAVOLR = 0x1B2, kBVOLL = 0x1B4, kBVOLR = 0x1B6,
    kMVOLXL = 0x1B8, kMVOLXR = 0x1BA, kReverbRegs = 0x1C0, kVoiceVolumes = 0x200,
  };
  // ATTR (SPUCNT) bits.
  enum : u16 {
    kAttrCdEnable = 1 << 0, kAttrCdReverb = 1 << 2, kAttrIrqEnable = 1 << 6,
    kAttrReverbEnable = 1 << 7, kAttrUnmute = 1 << 14, kAttrEnable = 1 << 15,
  };
  enum class TransferMode : u8 { Stop = 0, ManualWrite = 1, DmaWrite = 2, DmaRead = 3 };
  static constexpr u32 kFifoSize = 32;

  // Registers (spu_registers.cpp).
  u16 read16(u32 offset);
  void write16(u32 offset, u16 value);
  u16 read_voice(u32 v, u32 reg) const;
  void write_voice(u32 v, u32 reg, u16 value);
  void write_attr(u16 value);
  u16 status() const;
  static void set_half(u32& bits, u32 offset, u16 value);

  // Transfers and the RAM IRQ (spu_transfer.cpp).
  TransferMode transfer_mode() const { return static_cast<TransferMode>((attr_ >> 4) & 3); }
  void fifo_push(u16 value);
  void flush_fifo();
  void ram_write16(u32 byte_addr, u16 value);
  u16 ram_read16(u32 byte_addr);
  // Every voice checks two addresses each sample, so this stays inline.
  void check_irq(u32 byte_addr) {
    // IRQ9 needs both the IRQ enable and the SPU enable (ATTR bits 6 and 15).
    if ((attr_ & (kAttrIrqEnable | kAttrEnable)) != (kAttrIrqEnable | kAttrEnable)) return;
    if (((byte_addr & (kRamSize - 1)) >> 3) == irq_address_) raise_irq();
  }
  void raise_irq();

  // Lazy generation (spu.cpp). next_sample_ is when the first sample not yet made is due.
  void on_sample();
  void catch_up(Cycles horizon);
  // Steps the voices not yet `stepped` whose output nothing reads (voices_needed) or is 0
  // (Voice::silent), or that only their capture buffer reads (captured_only), through the
  // `samples` samples after the one just made, where that is exact; returns them with `stepped`
  // (bit mask) for the sample-by-sample loop to skip.
  u32 step_unheard_voices(u32 samples, u32 stepped);
  // Voices 1 and 3 where only their capture buffers read their outputs.
  u32 captured_only() const;
  // Where a captured voice's outputs for the next `samples` samples go.
  s16* captured_buffer(u32 voice, u32 samples);
  // Voice 1's or 3's output for the sample with `later` samples after it in the catch-up: stepped
  // ahead (captured_), or the one sample_voice() just made.
  s16 capture_output(u32 voice, u32 later) const {
    if (!(captured_ & (1u << voice))) return voices_[voice].output;
    return captured_out_[voice / 2][captured_samples_ - 1 - later];
  }
  // The outputs of the catch-up's last `count` samples of voice 1 or 3 if stepped ahead, else null.
  const s16* captured_tail(u32 voice, u32 count) const {
    return (captured_ & (1u << voice)) ? captured_out_[voice / 2].data() + captured_samples_ - count : nullptr;
  }
  // Whether a sample could raise IRQ9: both enables set and the flag not already up (a raised
  // flag stays until ATTR acknowledges it, so further hits change nothing).
  bool irq_possible() const {
    return (attr_ & (kAttrIrqEnable | kAttrEnable)) == (kAttrIrqEnable | kAttrEnable) && !irq_flag_;
  }
  Cycles next_booking() const;
  void book();

  // Sample generation (spu_mixer.cpp). Voices in `skip` were already stepped through this
  // sample (step_unheard_voices); `later` samples follow in the same catch-up (0 where nothing
  // may be left out); `reverb_made`: the catch-up made the reverb's ticks already.
  void generate_sample(u32 skip, u32 later, bool reverb_made);
  // Whether the rest of a catch-up, after a sample that left the voices in `skip`, is silence
  // that changes only counters, and n such samples at once.
  bool quiet_from_here(u32 skip) const;
  void quiet_samples(u32 n, bool reverb_made);
  // One reverb tick on the sample's reverb input (skipped, owed or made: see its body); the wet
  // output where heard, else 0.
  StereoSample reverb_sample(s32 in_left, s32 in_right, u32 later);
  // n output samples `out` to the taker and a running capture.
  void push_output(StereoSample out, u32 n);
  void apply_key_events();
  struct Mix {
    s32 left = 0, right = 0, reverb_left = 0, reverb_right = 0;
  };
  // Whether the output samples are kept (observed, or a capture running), and whether the mix is
  // made at all (also while a loudness watch waits for a loud sample).
  bool output_taken() const { return observed_ || capture_.active(); }
  bool mixing() const { return output_taken() || (loud_threshold_ && !loud_); }
  // Whether the mix hears the reverb's output (EVOLL/EVOLR).
  bool reverb_heard() const { return mixing() && (reverb_volume_left_ != 0 || reverb_volume_right_ != 0); }
  // Unheard, without writes (ATTR bit 7) or a possible IRQ9, a reverb tick's value matters only
  // if the output is heard before it is overwritten (Reverb::unseen_tick).
  bool reverb_unseen() const { return !reverb_heard() && !(attr_ & kAttrReverbEnable) && !irq_possible(); }
  // Whether no voice (EON) and no CD input feed the reverb: its input is 0.
  bool reverb_unfed() const { return reverb_on_ == 0 && !(attr_ & kAttrCdReverb); }
  // Voices (bit mask) whose output this sample is read by anything.
  u32 voices_needed() const;
  // One voice's sample: IRQ checks, envelope, pitch and block advance always; its output (into
  // Voice::output) and contribution to `mix` only when `needed`.
  void sample_voice(u32 i, bool needed, Mix& mix);
  void write_capture_buffers(StereoSample cd, s16 voice1, s16 voice3);
  void next_sample_state(StateIO& s, u32 version);

  Scheduler& sched_;
  InterruptController& irq_;
  AudioFifo& cd_audio_;
  Scheduler::Handle sample_event_;
  Cycles next_sample_ = 0;
  u32 max_batch_ = kDefaultMaxBatch;
  bool batches_end_at_flips_ = false;

  std::vector<u8> ram_;
  std::array<spu::Voice, kNumVoices> voices_{};
  spu::AdpcmBlockCache blocks_;  // the voices' decoded blocks (a cache: not state)
  spu::Reverb reverb_;
  spu::NoiseGenerator noise_;
  spu::VolumeSweep main_left_, main_right_;
  s16 cd_volume_left_ = 0, cd_volume_right_ = 0;      // AVOLL/AVOLR
  s16 ext_volume_left_ = 0, ext_volume_right_ = 0;    // BVOLL/BVOLR (external input is silent)
  s16 reverb_volume_left_ = 0, reverb_volume_right_ = 0;  // EVOLL/EVOLR
  u32 key_on_ = 0, key_off_ = 0;  // written KON/KOFF bits, applied on the next sample
  u32 pitch_mod_ = 0, noise_on_ = 0, reverb_on_ = 0, endx_ = 0;
  u16 attr_ = 0;
  bool irq_flag_ = false;  // STAT bit 6
  u16 irq_address_ = 0;    // IRQA, 8-byte units
  u16 transfer_start_ = 0; // TSA, 8-byte units
  u32 transfer_addr_ = 0;  // current transfer address in bytes
  u16 ram_control_ = 0;    // 1F801DACh
  std::array<u16, kFifoSize> fifo_{};
  u32 fifo_count_ = 0;
  u32 capture_pos_ = 0;    // halfword index into each 1 KiB capture buffer
  // Within a catch-up: voices 1 and 3 stepped ahead (bits 1 and 3), and their outputs for the
  // catch-up's last captured_samples_ samples.
  u32 captured_ = 0;
  std::array<std::vector<s16>, 2> captured_out_;
  u32 captured_samples_ = 0;
  // Read-back of registers with no other home (KON/KOFF last written, unknown registers).
  std::array<u16, kSize / 2> raw_{};

  std::vector<StereoSample> output_;
  size_t output_limit_ = kSampleRate * 60;
  bool observed_ = true;
  std::optional<u16> loud_threshold_;
  bool loud_ = false;  // a loud sample since the last take_loud()
  spu::AudioCapture capture_;
};

}  // namespace psx
