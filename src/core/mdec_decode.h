// MDEC decompression steps (psx-spx "MDEC Decompression"): run-length decoding of one 8x8 block
// with the quant table, the matrix IDCT with the uploaded scale table, and the YUV->RGB and Y->mono
// conversions of a macroblock. Pure functions, so they can be tested without the register file.
// The arithmetic (coefficient precision, where each IDCT pass drops bits, the colour factors and
// the 15-bit rounding) reproduces ps1-tests' hardware captures bit for bit (docs/fidelity.md):
// psx-spx's pseudo code and Mednafen's arithmetic are a level off in many of their pixels.
#pragma once
#include <array>
#include <cstddef>

#include "core/types.h"

namespace psx::mdec {

// Coefficients in 1/2 units (the hardware keeps one fraction bit after dequantisation).
using Block = std::array<s32, 64>;
using QuantTable = std::array<u8, 64>;
using ScaleTable = std::array<s16, 64>;
// IDCT output: signed 8-bit samples, row-major.
using Samples = std::array<s8, 64>;

// zigzag[position] = scan index of the coefficient at that position (psx-spx table).
extern const std::array<u8, 64> kZigzag;

// Decodes one block starting at src[pos] (halfwords). FE00h before the first value is padding;
// FE00h, a run past index 63, or a value written at index 63 ends the block. Returns false and
// leaves `pos` unchanged when the data ends before the block does.
bool rl_decode_block(const u16* src, size_t size, size_t& pos, const QuantTable& qt, Block& blk);

// The hardware IDCT: two passes of a matrix multiply by the scale table (its upper 13 bits, then
// its upper 12), each product and the first pass's sums truncated to a fixed precision, the result
// rounded, wrapped to 9 bits and saturated to signed 8 bits.
void idct(const ScaleTable& scale, const Block& blk, Samples& out);

// 16x16 pixels, 3 unsigned components (R, G, B) each, from Cr, Cb (8x8, upsampled) and Y1..Y4:
// 8-bit components for 24-bit output, 5-bit ones (0..31) for 15-bit output.
using Rgb16x16 = std::array<u8, 16 * 16 * 3>;
void yuv_to_rgb(const Samples& cr, const Samples& cb, const Samples& y, u32 xx, u32 yy, bool five_bit,
                Rgb16x16& out);

// 8-bit output byte of a sample; 4-bit output nibble (rounded, psx-spx "4bit mono").
u8 mono8(s8 y, bool is_signed);
u8 mono4(s8 y, bool is_signed);
// 15-bit output halfword (bit 15 clear) of three unsigned 5-bit components.
u16 rgb15(const u8* rgb, bool is_signed);

}  // namespace psx::mdec
