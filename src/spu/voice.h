// One of the 24 SPU voices (psx-spx "SPU ADPCM Samples", "SPU ADPCM Pitch"): its registers
// (volumes, pitch, start/repeat addresses, ADSR), the ADPCM block it is playing with the loop
// flag behaviour, the pitch counter and the interpolation history.
#pragma once
#include <array>

#include "core/state.h"
#include "core/types.h"
#include "spu/adpcm.h"
#include "spu/adpcm_cache.h"
#include "spu/envelope.h"

namespace psx::spu {

class Voice {
 public:
  // What happened when the pitch counter moved on.
  enum class BlockEvent : u8 { None, NextBlock, LoopEnd };

  // Registers at 1F801C00h + 10h*N.
  VolumeSweep volume_left;   // +0 VOLL
  VolumeSweep volume_right;  // +2 VOLR
  u16 pitch = 0;             // +4 PITCH (1000h = 44.1 kHz)
  u16 start_address = 0;     // +6 SSA, in 8-byte units
  Adsr adsr;                 // +8/+A ADSR1/ADSR2, +C ENVX
  u16 repeat_address = 0;    // +E LSAX, in 8-byte units

  // Key on: restart at SSA with an empty history and the envelope in Attack.
  void key_on();
  void key_off() { adsr.key_off(); }
  // A write to LSAX while the voice plays wins over the next LoopStart flag (psx-spx LSAX:
  // writing it redirects a playing sample; the flag must not overwrite that choice).
  void write_repeat_address(u16 value);

  // Loads and decodes the block at the current address if not loaded yet (through `blocks`); a
  // LoopStart flag copies the current address into LSAX.
  void fetch_block(const u8* ram, AdpcmBlockCache& blocks);
  // The interpolated sample at the pitch counter (call after fetch_block).
  s32 interpolate() const;
  // Adds the (already modulated and clipped) step to the pitch counter. Leaving the block
  // either moves to the next one or, with LoopEnd, jumps to LSAX; End without Repeat silences
  // the voice unless it plays noise (the ADPCM flags still advance then).
  BlockEvent advance(u32 step, bool noise);

  // Silent: the envelope Off at level 0 (its tick does nothing, the output is 0) and both volumes
  // fixed and latched (their ticks change nothing). Such a voice only moves its pitch counter.
  bool silent() const {
    return adsr.phase() == Adsr::Phase::Off && adsr.level() == 0 && volume_left.latched() && volume_right.latched();
  }
  // Sound RAM the SPU itself does not write during a run of samples (byte range [begin, end)).
  struct RamWindow {
    u32 begin = 0, end = 0;
  };
  // Steps a voice whose output nothing reads over `samples` (>= 1) samples at a constant, already
  // clipped `step`, crossing by crossing instead of sample by sample: between crossings the
  // envelope and the volume sweeps tick (nothing for a silent voice), each block crossed into is
  // decoded as the sample-by-sample loop would (the ADPCM history and LSAX stay exact), LoopEnd
  // jumps and sets `loop_end`, and End+Mute turns the envelope off after that sample's tick.
  // Blocks are read from `ram` as it is at the run's first sample; one read later that lies
  // outside `unwritten` could have changed in between: then it returns false and the voice is
  // left half-stepped (the caller restores it and steps it sample by sample).
  bool step_unheard(const u8* ram, AdpcmBlockCache& blocks, u32 step, bool noise, u32 samples, RamWindow unwritten,
                    bool& loop_end);

  // Steps a voice whose output only the capture buffers read (voices 1 and 3) over `samples`
  // samples as step_unheard() does, but sample by sample, writing each sample's output (after the
  // envelope, psx-spx "SPU Memory layout") to out[0..samples). No noise. Returns false on the
  // same block reads as step_unheard(), leaving the voice half-stepped.
  bool step_captured(const u8* ram, AdpcmBlockCache& blocks, u32 step, u32 samples, RamWindow unwritten, s16* out,
                     bool& loop_end);

  u16 current_address() const { return current_address_; }
  // Byte address of the halfword holding the current sample (for the IRQ address check).
  u32 data_address() const { return current_address_ * 8u + 2 + ((counter_ >> 12) / 4) * 2; }

  // Sample after the envelope (OUTX): feeds pitch modulation of the next voice and, for voices
  // 1 and 3, the capture buffers. Computed each sample before any use, so it is state only where
  // the capture buffers reuse it while the SPU is disabled (voices 1 and 3, saved by the SPU).
  s16 output = 0;

  // `with_output`: the layout before SPU section version 2, which saved every voice's output.
  void do_state(StateIO& s, bool with_output);

 private:
  u16 current_address_ = 0;
  u32 counter_ = 0;  // bits 12+: sample in block, bits 4-11: interpolation index
  bool has_block_ = false;
  bool ignore_loop_start_ = false;
  u8 block_flags_ = 0;
  AdpcmHistory history_;
  // Three samples from the previous block, then the 28 of the current block.
  std::array<s16, 3 + kAdpcmBlockSamples> samples_{};
};

}  // namespace psx::spu
