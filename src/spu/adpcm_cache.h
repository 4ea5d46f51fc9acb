// Decoded SPU-ADPCM blocks remembered by everything their decoding depends on: the block's 16
// bytes and the history it starts from (decode_adpcm_block() is a function of those alone). A
// game plays the same few sounds over and over, so a voice mostly meets a block again from the
// history it met it with: 99.9% of Tumble's block fetches. A hit copies the 28 samples and the
// history after them instead of running the decoder's prediction filter sample by sample. The
// table is a cache, not state: a miss decodes and replaces the entry, and what a voice gets is
// the same either way.
#pragma once
#include <array>

#include "core/types.h"
#include "spu/adpcm.h"

namespace psx::spu {

class AdpcmBlockCache {
 public:
  struct Decoded {
    std::array<s16, kAdpcmBlockSamples> samples{};
    AdpcmHistory history;  // after the block
  };
  // decode_adpcm_block(ram + address, history, ...) as it would decode: the samples and the
  // history after. `address`: the block's byte address in the 512 KiB of sound RAM (a multiple
  // of 8; a block in the last 8 bytes goes on at the start), which picks the entry: a sound's
  // blocks, one after the other, never share one.
  const Decoded& decode(const u8* ram, u32 address, const AdpcmHistory& history);

 private:
  // 2048 entries (160 KiB): blocks 16 KiB apart share one. Tumble's sounds meet 447 blocks and
  // histories; 1,414 of its 164,332 fetches in 100 moves miss (0.9%). An entry still all zeros
  // is the right answer for its key: an all-zero block (filter 0, shift 0) from an all-zero
  // history decodes to zeros.
  static constexpr u32 kEntries = 2048;
  struct Entry {
    u64 low = 0, high = 0;  // the block's bytes 0-7 and 8-15 (host order)
    u32 history = 0;        // old | older << 16 before the block
    Decoded out;
  };
  std::array<Entry, kEntries> entries_{};
};

}  // namespace psx::spu
