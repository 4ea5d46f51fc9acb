// The SPU reverb unit (psx-spx "SPU Reverb Registers", "SPU Reverb Formula"): a stereo
// Schroeder reverberator running at 22.05 kHz on a work area in sound RAM (ESA..7FFFEh), with
// the 39-tap FIR resampling between the 44.1 kHz mixer and the 22.05 kHz core. Left is computed
// on one 44.1 kHz cycle and right on the next, as the hardware does.
#pragma once
#include <array>

#include "core/audio_fifo.h"
#include "core/state.h"
#include "core/types.h"

namespace psx::spu {

class Reverb {
 public:
  // Register indices into regs (1F801DC0h + 2*index), names from psx-spx.
  enum Reg : u32 {
    dAPF1, dAPF2, vIIR, vCOMB1, vCOMB2, vCOMB3, vCOMB4, vWALL, vAPF1, vAPF2,
    mLSAME, mRSAME, mLCOMB1, mRCOMB1, mLCOMB2, mRCOMB2, dLSAME, dRSAME, mLDIFF, mRDIFF,
    mLCOMB3, mRCOMB3, mLCOMB4, mRCOMB4, dLDIFF, dRDIFF, mLAPF1, mRAPF1, mLAPF2, mRAPF2, vLIN, vRIN,
  };
  // Written by the SPU, which settles owed values first (settle()).
  std::array<u16, 32> regs{};

  // ESA (1F801DA2h): the work area start; writing it also resets the buffer address.
  void write_base(u16 value);
  u16 base() const { return base_; }

  // Where a reverb access touched sound RAM this tick at the IRQ address (8-byte units). Enabled
  // only where a hit would matter (IRQ9 could fire); disabled, reads have no effect at all.
  struct IrqWatch {
    bool enabled = false;
    u32 unit = 0;
    bool hit = false;
  };

  // One 44.1 kHz tick. `in` is the sum of reverb-enabled voices and CD audio; the result is the
  // reverb output before the EVOLL/EVOLR volumes, computed only if `want_output` (zero
  // otherwise: the output filter holds no state of its own). Writes to the work area only when
  // `write_enable` (ATTR bit 7); reads always happen.
  StereoSample tick(s32 in_left, s32 in_right, u8* ram, bool write_enable, bool want_output, IrqWatch& irq);
  // A tick whose 22.05 kHz value nobody reads: it is overwritten in the output history
  // (kRing entries per side, one side a tick) kTicksToOverwrite ticks later, before any read.
  // Valid only when the tick has no other effect: no work-area writes (ATTR bit 7 clear), no
  // IRQ9 possible from its reads, no output wanted meanwhile. Then only the input history and
  // the positions move.
  static constexpr u32 kTicksToOverwrite = 128;
  void skip_tick(s32 in_left, s32 in_right);
  // A tick under the same conditions whose value could be read later (by an output wanted
  // again): the value is owed, computed only when something could see it (settle()). Until
  // then nothing may write the sound RAM it reads, change the registers or ESA: the SPU settles
  // first. The capture buffers (sound RAM 0..FFFh) are written every sample, so a tick reading
  // them is computed at once.
  void owe_tick(s32 in_left, s32 in_right, u8* ram);
  // A tick nobody can see now (no writes, no IRQ9, no output wanted), with `later` ticks after it
  // in the same catch-up (nothing observes the SPU before its end): skipped where its value is
  // overwritten within them, owed otherwise.
  void unseen_tick(s32 in_left, s32 in_right, u32 later, u8* ram) {
    if (later >= kTicksToOverwrite) skip_tick(in_left, in_right);
    else owe_tick(in_left, in_right, ram);
  }
  // n unseen ticks of input 0 that end a catch-up (the k-th has n-1-k after it), as n
  // unseen_tick() calls would make them, where none of them reads a capture buffer word (so
  // every value is skipped or owed, and the capture buffers' writes meanwhile reach none):
  // the skipped ones at once, the owed ones in a loop. Returns false, changing nothing, where
  // one may read a capture buffer word.
  bool quiet_ticks(u32 n);
  // Computes the owed values (tick() does it first; so must a save). Without writes (as owed)
  // process_side() only reads `ram`.
  void settle(u8* ram);
  bool owes() const { return (owed_[0] | owed_[1]) != 0; }

  // Saving settles first (the owed values are state); loading forgets them.
  void do_state(StateIO& s, u8* ram);

 private:
  static constexpr u32 kRing = 64;
  static constexpr u32 kCaptureHalfwords = 0x800;  // the capture buffers, sound RAM 0..FFFh
  static_assert(kTicksToOverwrite == 2 * kRing);
  void push_input(s32 in_left, s32 in_right);
  // The buffer address's move after each right-side tick, wrapping to ESA.
  u32 moved(u32 address) const;
  void step_address();
  void step_address(u32 k);  // k of them at once
  void end_tick();
  // m zero inputs, as push_input(0, 0) m times.
  void push_zero_inputs(u32 m);
  // What skip_tick(0, 0) does m times, after its inputs (push_zero_inputs).
  void skip_quiet(u32 m);
  // The value of this tick's slot `pos` on `side`: computed now where it reads a capture buffer,
  // else owed.
  void owe(u32 side, u32 pos, u8* ram);
  // The side's 22.05 kHz value, with the buffer address `current` (in halfwords).
  s16 process_side(u32 side, s32 input, u32 current, u8* ram, bool write_enable, IrqWatch& irq);
  // How many ticks from this one on (either side) surely read no capture buffer word, without
  // writes: 0 if this one may.
  u32 ticks_clear_of_capture() const;
  // The work area as one tick sees it: ESA's start, its size and the buffer address's offset
  // into it, all in halfwords; at() turns a register-relative offset into a halfword address.
  struct Area {
    Area(u16 base, u32 current);
    u32 at(s32 rel_halfwords) const;  // inline below: 14 calls a tick
    s32 start, size, offset;
  };
  static s16 read(u32 halfword, const u8* ram, IrqWatch& irq);
  static void write(u32 halfword, s32 value, u8* ram, bool write_enable, IrqWatch& irq);
  s32 downsample(u32 side) const;
  s32 upsample(u32 side, bool fresh) const;

  u16 base_ = 0;
  u32 current_ = 0;  // buffer address in halfwords
  u32 phase_ = 0;    // 0: left's cycle, 1: right's cycle
  u32 in_pos_ = 0;
  std::array<u32, 2> out_pos_{};  // newest 22.05 kHz output of each side
  std::array<std::array<s16, kRing>, 2> in_history_{};   // 44.1 kHz inputs
  std::array<std::array<s16, kRing>, 2> out_history_{};  // 22.05 kHz outputs
  // Consecutive ticks whose inputs were both 0 (up to kRing; not state: a load restarts it at 0).
  // From 39 on, every tap downsample() reads is 0.
  u32 zero_inputs_ = 0;
  // The owed values (owe_tick): a bit per output history slot, and the buffer address each is
  // computed at. Its input is not kept: without writes or an IRQ watch process_side() leaves
  // out the reflections, the only part that reads it.
  std::array<u64, 2> owed_{};
  std::array<std::array<u32, kRing>, 2> owed_at_{};
  // Ticks left of the last ticks_clear_of_capture() (counted down by every tick; reset where the
  // registers or ESA may change: settle(), write_base(), a load).
  u32 clear_ticks_ = 0;
};

inline u32 Reverb::Area::at(s32 rel) const {
  // psx-spx "SPU Reverb Formula": addresses wrap inside ESA..7FFFEh
  // (halfwords start .. 3FFFFh). |offset + rel| stays below 2^20, so 32-bit arithmetic is exact.
  // Within one wrap either way (every delay shorter than the area, as in every game's preset) a
  // subtraction or addition gives the remainder; only larger distances need the division.
  s32 off = offset + rel;
  if (off >= size) off -= size;
  else if (off < 0) off += size;
  if (off < 0 || off >= size) {  // more than one wrap away
    off %= size;
    if (off < 0) off += size;
  }
  return static_cast<u32>(start + off);
}

}  // namespace psx::spu
