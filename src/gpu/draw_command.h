// One renderer call kept for later (deferred drawing, draw_queue.h), and the VRAM rectangles it
// may write, may read, and surely overwrites. Write and read rectangles are supersets of what the
// renderer touches (conservative: a command never touches VRAM outside them); the overwrite
// rectangle is a subset of what it replaces whatever VRAM held before (exact, from the same span
// rules the software rasterizer uses), or empty.
#pragma once
#include "core/types.h"
#include "gpu/renderer.h"

namespace psx::gpu {

// A half-open VRAM rectangle [x0, x1) x [y0, y1); empty when x0 >= x1 or y0 >= y1.
struct Rect {
  s32 x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  bool empty() const { return x0 >= x1 || y0 >= y1; }
  bool intersects(const Rect& o) const {
    return !empty() && !o.empty() && x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
  }
  // An empty rectangle lies inside every rectangle.
  bool contains(const Rect& o) const {
    return o.empty() || (x0 <= o.x0 && o.x1 <= x1 && y0 <= o.y0 && o.y1 <= y1);
  }
  s64 area() const { return empty() ? 0 : s64{x1 - x0} * (y1 - y0); }
};

// A VRAM block starting at (x, y), wrapping at the VRAM edges: the block itself, or whole rows or
// the whole VRAM where it wraps (a superset, for write and read rectangles).
Rect wrapped_block(u32 x, u32 y, u32 width, u32 height);

// The VRAM operations' parameters. Fill: x, y, width, height, pixel. Copy: src (sx, sy) to
// (x, y), width x height, mask. Row: width pixels at (x, y) from the queue's pixel store at
// `pixels`, mask.
struct VramBlock {
  u32 x = 0, y = 0, width = 0, height = 0, sx = 0, sy = 0;
  u16 pixel = 0;
  MaskMode mask;
  u32 pixels = 0;
};

// A GP0 four-point polygon, kept whole: the hardware draws it as two triangles, `first` and then
// (first.v[1], first.v[2], last) with the same attributes (second()).
struct Quad {
  Triangle first;
  Vertex last;

  Triangle second() const {
    Triangle t = first;
    t.v[0] = first.v[1], t.v[1] = first.v[2], t.v[2] = last;
    return t;
  }
};

struct DrawCommand {
  // ClutLoad: only the CLUT cache load of a textured call the queue dropped (block: x, y and the
  // entry count as width), kept where a later kept call draws with what it loads.
  enum class Kind : u8 { Triangle, Quad, Line, Rectangle, Fill, Copy, Row, ClutLoad };
  Kind kind = Kind::Fill;
  // Triangle, Quad, Rectangle: CLUT cache entries loaded before drawing (Renderer::load_clut()
  // from the call's CLUT position): 0, 16 or 256.
  u16 clut_load = 0;
  DrawState ds;  // Triangle, Quad, Line, Rectangle
  // The call's parameters, by kind: queued calls are copied a lot (kept, compacted), so only one
  // kind's take room, and every reader checks `kind` first.
  union {
    Triangle triangle;
    Quad quad;
    Line line;
    Rectangle rectangle;
    VramBlock block;  // Fill, Copy, Row
  };
  // Set by the queue: write_rect(), computed once (pruning asks for it often), and what this
  // call (with the next one, for a pair of triangles) surely replaces.
  Rect write;
  Rect cover;
  bool cover_with_next = false;
  // read_rects(), kept by the queue once pruning first asks (kReadsUnknown before).
  static constexpr u8 kReadsUnknown = 0xFF;
  u8 read_count = kReadsUnknown;
  Rect reads[3];

  DrawCommand() : block() {}

  Rect write_rect() const;
  // Up to three rectangles of VRAM whose contents change what the command writes; returns the
  // count. Reads `write` (set first).
  u32 read_rects(Rect out[3]) const;
  // What the command replaces whatever was there (fills, opaque untextured rectangles without
  // the mask check); triangles and quads are handled as pairs of triangles by
  // triangle_pair_cover.
  Rect overwrite_rect() const;
  // A textured call: it may draw with the CLUT cache as earlier calls left it.
  bool textured() const;
  // The CLUT position of a textured call.
  u32 clut_x() const;
  u32 clut_y() const;
};

// One of a pair of triangles drawn one after the other, with its drawing state.
struct DrawnTriangle {
  const Triangle& t;
  const DrawState& ds;
};

// The rectangle two triangles drawn one after the other surely replace together (a quad's two
// halves, e.g. a full-screen Gouraud background), or empty when their union is not a rectangle
// or either could keep old pixels (textured, semi-transparent, mask check, interlaced rows).
Rect triangle_pair_cover(DrawnTriangle first, DrawnTriangle second);
// A test that costs a few comparisons, false for most pairs triangle_pair_cover() would answer
// empty: either triangle may keep old pixels, their drawing areas differ, or a vertex inside the
// drawing area lies off the corners of the pair's bounding box (two triangles make a rectangle
// only with their six vertices at its four corners; clipped away, a vertex may lie anywhere).
// The last is a shortcut, not an exact test: an odd pair it turns away only drops less.
bool may_pair_cover(DrawnTriangle first, DrawnTriangle second);

}  // namespace psx::gpu
