// The OpenGL renderer's shader programs: "draw" runs every VRAM-writing operation but fills
// (polygons, rectangles, lines, VRAM copies, CPU uploads) with the PlayStation's per-pixel rules,
// and "downsample" reduces the scaled VRAM to 1024x512 for read-back. Sources are in
// gl_shaders.cpp; the per-primitive record they read is PrimitiveRecord.
#pragma once
#include <string>

#include "core/types.h"
#include "gpu/gl/gl_functions.h"

namespace psx::gpu::gl {

// What the draw program draws for one record (flags bits 0-2).
enum class Kind : u32 { Triangle = 0, Rectangle = 1, Line = 2, Copy = 3, Upload = 4 };

// Flags bits above the kind.
namespace flag {
constexpr u32 kTexShift = 3;         // 2 bits: 0 untextured, 1 4-bit CLUT, 2 8-bit CLUT, 3 15-bit
constexpr u32 kRaw = 1u << 5;
constexpr u32 kSemi = 1u << 6;
constexpr u32 kSemiModeShift = 7;    // 2 bits, GP0(E1).5-6
constexpr u32 kDither = 1u << 9;
constexpr u32 kCheckMask = 1u << 10;
constexpr u32 kSetMask = 1u << 11;
constexpr u32 kSkipShift = 12;       // 2 bits: 0 draw every row, 1 skip even rows, 2 skip odd rows
constexpr u32 kLongEdgeLeft = 1u << 14;
}  // namespace flag

// One primitive as the draw program reads it: eight ivec4 instance attributes. The meaning of
// a/b/c, base and grad depends on the kind (gl_primitives.cpp fills them, the shader reads them).
struct PrimitiveRecord {
  s32 bbox[4];     // native pixels x0, y0, x1, y1 (half-open), already clipped to the drawing area
  s32 flags;       // Kind | flag bits
  s32 page;        // texture page x | y << 16
  s32 spare;       // unused (4- and 8-bit texels take their colours from the palette texture)
  s32 window;      // and_u | or_u << 8 | and_v << 16 | or_v << 24
  s32 a[2], b[2], c[2], extra[2];
  s32 base[5];     // r, g, b, u, v
  s32 grad[10];    // d/dx, d/dy of r, g, b, u, v
  s32 pad;
};
static_assert(sizeof(PrimitiveRecord) == 8 * 16, "eight ivec4 attributes");
constexpr u32 kRecordVec4s = 8;

struct Programs {
  GLuint downsample = 0;
  GLint downsample_scale = -1;
};

// Compiles and links the downsample program; false with `error` holding the compiler's log.
bool build_programs(const GlFunctions& gl, Programs& out, std::string& error);

// The draw program comes in variants, one per kind, texture mode, raw, semi-transparency and
// mask check (the flags that change what a fragment computes): an 8-bit key.
constexpr u32 kDrawVariants = 256;
u32 variant_of(s32 flags);

struct DrawProgram {
  GLuint program = 0;
};
// Compiles and links one variant of the draw program for a renderer at `scale`.
bool draw_variant(const GlFunctions& gl, u32 variant, u32 scale, DrawProgram& out, std::string& error);

}  // namespace psx::gpu::gl
