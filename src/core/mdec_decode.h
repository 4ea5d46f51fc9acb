// MDEC decompression steps (psx-spx "MDEC Decompression"): run-length decoding of one 8x8 block
// with the quant table, the matrix IDCT with the uploaded scale table, and the YUV->RGB and Y->mono
// conversions of a macroblock. Pure functions, so they can be tested without the register file.
#pragma once
#include <array>
#include <cstddef>

#include "core/types.h"

namespace psx::mdec {

using Block = std::array<s32, 64>;
using QuantTable = std::array<u8, 64>;
using ScaleTable = std::array<s16, 64>;

// zigzag[position] = scan index of the coefficient at that position (psx-spx table).
extern const std::array<u8, 64> kZigzag;

// Decodes one block starting at src[pos] (halfwords). FE00h before the first value is padding;
// FE00h (or a run past index 63) ends the block. Returns false and leaves `pos` unchanged when the
// data ends before the block does.
bool rl_decode_block(const u16* src, size_t size, size_t& pos, const QuantTable& qt, Block& blk);

// The hardware IDCT: two passes of a plain matrix multiply by the scale table's upper 13 bits.
void idct(const ScaleTable& scale, Block& blk);

// 16x16 pixels, 3 bytes (R, G, B) each, from Cr, Cb (8x8, upsampled) and Y1..Y4 (8x8 each).
using Rgb16x16 = std::array<u8, 16 * 16 * 3>;
void yuv_to_rgb(const Block& cr, const Block& cb, const Block& y, u32 xx, u32 yy, bool is_signed, Rgb16x16& out);

// 8x8 luminance bytes.
using Mono8x8 = std::array<u8, 64>;
void y_to_mono(const Block& y, bool is_signed, Mono8x8& out);

}  // namespace psx::mdec
