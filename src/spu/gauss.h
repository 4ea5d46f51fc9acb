// The SPU's 4-point "Gaussian" interpolation between ADPCM samples (psx-spx "4-Point Gaussian
// Interpolation"): a 512-entry hardware table indexed by bits 4-11 of the voice's pitch counter.
#pragma once
#include <array>

#include "core/types.h"

namespace psx::spu {

extern const std::array<s16, 512> kGaussTable;

// Interpolates between the four most recent samples with the 8-bit index i (00h..FFh).
// Each product is shifted right by 15 before summing, as psx-spx gives it.
inline s32 gauss_interpolate(s16 oldest, s16 older, s16 old, s16 newest, u32 i) {
  s32 out = (kGaussTable[0x0FF - i] * oldest) >> 15;
  out += (kGaussTable[0x1FF - i] * older) >> 15;
  out += (kGaussTable[0x100 + i] * old) >> 15;
  out += (kGaussTable[0x000 + i] * newest) >> 15;
  return out;
}

}  // namespace psx::spu
