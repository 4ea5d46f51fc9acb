// XA-ADPCM audio (psx-spx "CDROM XA Audio ADPCM Compression"): decodes the 18 sound groups of a
// Form 2 audio sector (4- or 8-bit samples, mono or stereo, 37.8 or 18.9 kHz) and resamples the
// result to the SPU's 44.1 kHz the way the CD decoder does: 18.9 kHz samples are doubled to
// 37.8 kHz, every 37.8 kHz sample enters a 32-entry ring buffer, and after every sixth one the
// seven 29-point "zigzag" tables give seven 44.1 kHz samples.
#pragma once
#include <vector>

#include "core/audio_fifo.h"
#include "core/state.h"
#include "core/types.h"

namespace psx {

class XaAdpcm {
 public:
  static constexpr u32 kRingSize = 32;     // ringbuf[p AND 1Fh]
  static constexpr u32 kZigZagTaps = 29;   // TableX[1..29]
  static constexpr u32 kZigZagTables = 7;  // seven outputs per six inputs
  static constexpr u32 kSixStep = 6;

  // Coding info byte of the subheader: bit 0 stereo, bit 2 18.9 kHz, bit 4 8-bit samples.
  static bool stereo(u8 coding) { return (coding & 0x03) == 1; }
  static bool half_rate(u8 coding) { return (coding & 0x0C) == 4; }
  static bool eight_bit(u8 coding) { return (coding & 0x30) == 0x10; }

  // Decodes the 18 sound groups (2304 bytes) that start at `data` (raw sector offset 24) and
  // appends 44.1 kHz stereo frames to `out`.
  void decode_sector(const u8* data, u8 coding, std::vector<StereoSample>& out);
  // Forgets decoder history and the resampler's ring buffer (a new stream: seek, Setfilter, reset).
  void reset();

  void do_state(StateIO& s);

 private:
  void decode_group(const u8* group, bool eight, bool st, s16* left, s16* right, u32& nl, u32& nr);
  s16 decode_unit_sample(s32 raw, u32 shift, u32 filter, s32 hist[2]);
  void output_37800hz(s16 l, s16 r, std::vector<StereoSample>& out);
  s16 zigzag_interpolate(const s16* ringbuf, u32 table) const;

  s32 hist_[2][2] = {};              // [channel][older, old] decoder history
  s16 ringbuf_[2][kRingSize] = {};   // [channel] last 32 samples at 37.8 kHz
  u32 p_ = 0;                        // next ring buffer slot (0..31)
  u32 sixstep_ = kSixStep;           // 37.8 kHz samples until the next seven outputs (1..6)
};

}  // namespace psx
