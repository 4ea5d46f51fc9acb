// SPU-ADPCM (psx-spx "SPU ADPCM Samples"): 16-byte blocks of 28 four-bit samples with a
// shift/filter byte and loop flags. Holds the decoder used by the voices and the encoder used by
// the psxadpcm tool, by Tumble's sound effects and by the tests.
#pragma once
#include <cstddef>
#include <vector>

#include "core/types.h"

namespace psx::spu {

// The SPU's sound RAM, which holds the blocks; block addresses wrap within it.
constexpr u32 kSoundRamBytes = 512 * 1024;
constexpr u32 kAdpcmBlockBytes = 16;
constexpr u32 kAdpcmBlockSamples = 28;

// Flag bits, the second byte of a block.
enum AdpcmFlag : u8 {
  kAdpcmLoopEnd = 1,     // set ENDX, continue at the repeat address
  kAdpcmLoopRepeat = 2,  // with LoopEnd: keep playing; without: End+Mute
  kAdpcmLoopStart = 4,   // the repeat address becomes this block
};

// The decoder's memory: the two most recent output samples.
struct AdpcmHistory {
  s16 old = 0;
  s16 older = 0;
};

// Decodes one block into 28 samples, updating the filter history.
void decode_adpcm_block(const u8* block, AdpcmHistory& history, s16* out);

struct AdpcmEncodeOptions {
  // Loop the sample: the block holding `loop_start` (a sample index) gets LoopStart, the last
  // block LoopEnd+LoopRepeat. Without looping the last block is End+Mute, so the voice stops and
  // sets ENDX right after the sound.
  bool loop = false;
  u32 loop_start = 0;
};

// Encodes 16-bit PCM into ADPCM blocks: for each block, every filter and shift is tried against
// an exact model of the decoder (including clamping) and the smallest squared error wins.
// The input is padded with silence to a whole number of blocks (at least one block).
std::vector<u8> encode_adpcm(const s16* pcm, size_t count, const AdpcmEncodeOptions& options);

}  // namespace psx::spu
