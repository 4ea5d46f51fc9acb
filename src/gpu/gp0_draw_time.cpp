// How long the GPU is busy with a drawing command, for GPUSTAT's ready bits (psx-spx "GPU Status
// Register"; ps1-tests gpu/gpustat): bit 26 reads 0 while the GPU draws, bit 28 (and 25 in DMA
// direction 2) while a command waits in the FIFO for the one drawing. The time is a cost per pixel
// drawn, measured on a console by ps1-tests gpu/bandwidth
// (400 commands over a 320x240 screen, timed in HBlanks): the pixels a command covers in the
// drawing area times that cost, booked from the later of now and the end of the previous
// command. Computed from the command's words alone, so it never makes a deferred draw log draw.
// Every command a game sends comes through here, so the common cases avoid divisions.
#include <algorithm>
#include <cstdlib>

#include "gpu/gpu.h"

namespace psx {

namespace {
// CPU cycles per pixel in 1/4096 units: HBlanks * 2152.87 cycles (an NTSC scanline, 3413 video
// clocks of 53.693175 MHz; psx-spx "GPU Timings") / (399 * 76,800 pixels): the program reads its
// counter once the 400th command starts, 399 drawn. Fill 1216 HBlanks; rectangle 7603,
// semi-transparent 11455, textured 15138; polygon (quad) 7727, semi-transparent 11648, textured
// 39938; VRAM-to-VRAM copy 19132. Gouraud shading and lines were not measured: they cost what
// flat polygons do. For comparison, Mednafen charges 0.5 cycles a flat polygon pixel, 0.75 a
// semi-transparent one and 1 a textured one (no texture cache misses), about 0.077 a fill pixel.
constexpr s64 kFill = 350, kRect = 2188, kRectSemi = 3296, kRectTextured = 4356;
constexpr s64 kPoly = 2224, kPolySemi = 3352, kPolyTextured = 11493, kCopy = 5506;

// Positions as a command gives them (11-bit signed), before the drawing offset: a triangle's area
// and a line's length do not depend on where they lie, so the drawing area is moved by minus the
// offset instead (Gpu::time_area_, update_draw_state()), once per E3-E5 rather than per vertex.
struct Point {
  s32 x, y;
};
inline Point raw_position(u32 xy) { return {static_cast<s32>(xy << 21) >> 21, static_cast<s32>(xy << 5) >> 21}; }

inline s64 clipped(s32 x0, s32 y0, s32 x1, s32 y1, const gpu::TimeArea& a) {
  const s64 w = std::min(x1, a.right_end) - std::max(x0, a.left);
  const s64 h = std::min(y1, a.bottom_end) - std::max(y0, a.top);
  return w > 0 && h > 0 ? w * h : 0;
}

// Twice a triangle's area. Coordinates are 11 bits, so every product fits 32 bits.
inline s32 area2(Point a, Point b, Point c) {
  return std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

// A triangle's pixels: its area, scaled by the part of its bounding box inside the drawing area.
s64 triangle_pixels(Point a, Point b, Point c, const gpu::TimeArea& area) {
  const s32 x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
  const s32 y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
  const s64 box = s64{x1 - x0} * (y1 - y0);
  if (box == 0) return 0;
  return s64{area2(a, b, c) / 2} * clipped(x0, y0, x1, y1, area) / box;
}

// A polygon partly inside the drawing area (out of line: the common cases need none of it).
[[gnu::noinline]] s64 clipped_polygon_pixels(const Point* p, bool quad, const gpu::TimeArea& area) {
  return triangle_pixels(p[0], p[1], p[2], area) + (quad ? triangle_pixels(p[1], p[2], p[3], area) : 0);
}

// A polygon's pixels: its triangles' (the second of a quad is corners 1-3). Most polygons lie
// wholly inside the drawing area or wholly outside it; then each triangle's box does too (it lies
// in the polygon's), its clipped part is its whole box or nothing, and no division is needed.
s64 polygon_pixels(const u32* w, u32 c, const gpu::TimeArea& area) {
  const u32 stride = 1 + ((c >> 2) & 1) + ((c >> 4) & 1);  // position, texcoord, next colour
  const bool quad = c & 0x08;
  Point p[4] = {raw_position(w[1]), raw_position(w[1 + stride]), raw_position(w[1 + 2 * stride])};
  p[3] = quad ? raw_position(w[1 + 3 * stride]) : p[2];
  const s32 x0 = std::min(std::min(p[0].x, p[1].x), std::min(p[2].x, p[3].x));
  const s32 x1 = std::max(std::max(p[0].x, p[1].x), std::max(p[2].x, p[3].x));
  const s32 y0 = std::min(std::min(p[0].y, p[1].y), std::min(p[2].y, p[3].y));
  const s32 y1 = std::max(std::max(p[0].y, p[1].y), std::max(p[2].y, p[3].y));
  if (x1 <= area.left || x0 >= area.right_end || y1 <= area.top || y0 >= area.bottom_end) return 0;
  if (x0 < area.left || x1 > area.right_end || y0 < area.top || y1 > area.bottom_end)
    return clipped_polygon_pixels(p, quad, area);
  return area2(p[0], p[1], p[2]) / 2 + (quad ? area2(p[1], p[2], p[3]) / 2 : 0);
}
}  // namespace

Cycles Gpu::draw_time(const u32* w) const {
  const u32 c = w[0] >> 24;
  const bool semi = c & 0x02, textured = c & 0x04;
  s64 pixels = 0, cost = 0;
  switch (c >> 5) {
    case 1:  // polygon: bit 4 Gouraud, 3 quad, 2 textured
      pixels = polygon_pixels(w, c, time_area_);
      cost = textured ? kPolyTextured : semi ? kPolySemi : kPoly;
      break;
    case 2: {  // line (a polyline's first segment; the others come through book_line())
      const Point a = raw_position(w[1]), b = raw_position(w[(c & 0x10) ? 3 : 2]);
      pixels = std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)) + 1;
      cost = semi ? kPolySemi : kPoly;
      break;
    }
    case 3: {  // rectangle: bits 3-4 size
      const Point p = raw_position(w[1]);
      static constexpr s32 kSizes[4] = {0, 1, 8, 16};
      // Only a variable-size rectangle (size 0) has a width/height word: a 1x1, 8x8 or 16x16 one
      // ends before it (psx-spx "GPU Render Rectangle Commands").
      const u32 size = (c >> 3) & 3, wh = size ? 0 : w[textured ? 3 : 2];
      const s32 width = size ? kSizes[size] : s32(wh & 0x3FF), height = size ? kSizes[size] : s32((wh >> 16) & 0x1FF);
      pixels = clipped(p.x, p.y, p.x + width, p.y + height, time_area_);
      cost = textured ? kRectTextured : semi ? kRectSemi : kRect;
      break;
    }
    case 4:  // VRAM-to-VRAM copy
      pixels = s64{((w[3] - 1) & 0x3FF) + 1} * ((((w[3] >> 16) - 1) & 0x1FF) + 1);
      cost = kCopy;
      break;
    default:
      if (c != 0x02) return 0;
      pixels = s64{((w[2] & 0x3FF) + 0xF) & ~0xFu} * ((w[2] >> 16) & 0x1FF);  // GP0(02) fill
      cost = kFill;
  }
  // Pixels and costs are never negative: a shift, not a signed division.
  return static_cast<Cycles>(static_cast<u64>(pixels * cost) >> 12);
}

void Gpu::book_drawing(Cycles time) {
  if (time == 0) return;
  fifo_empty_at_ = std::max(busy_until_, sched_.now());  // it waits in the FIFO until then
  busy_until_ = fifo_empty_at_ + time;
}

// GPUSTAT's ready bits change when the FIFO empties and when the drawing ends. Idle-loop skipping
// (cpu/idle_skip.cpp) takes GPUSTAT to change only at events, so once a program reads GPUSTAT
// while the GPU is busy, an event ('gpu.draw', which does nothing but mark the time) is booked
// at the next change: a loop polling bit 26 or 28 wakes then, not at the next VBlank, and its
// next read books the change after. Without a read none is booked: a program that never polls
// costs no events. A pending booking is never later than the next change (the times only grow).
void Gpu::watch_drawing() {
  if (sched_.pending(draw_event_)) return;
  const Cycles now = sched_.now();
  if (fifo_empty_at_ > now) sched_.schedule_at(draw_event_, fifo_empty_at_);
  else if (busy_until_ > now) sched_.schedule_at(draw_event_, busy_until_);
}

// A VRAM-to-CPU block by DMA (direction 3): the GPU reads the block's pixels out of VRAM at the
// rate it writes a plain rectangle's (kRect), and the DMA's next block waits for them. ps1-tests
// gpu/bandwidth's console log: 400 reads of 320x240 in 16-word blocks took 15,770 HBlanks, 35.3
// cycles a block, where a write of the same blocks took 12,195 (27.3: the DMA's own time).
Cycles Gpu::dma_block_cycles(u32 words) const {
  return dma_direction_ == 3 ? static_cast<Cycles>(s64{words} * 2 * kRect / 4096) : 0;
}

void Gpu::book_line(const gpu::Vertex& a, const gpu::Vertex& b) {
  const s64 pixels = std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)) + 1;
  book_drawing(static_cast<Cycles>(pixels * (polyline_semi_ ? kPolySemi : kPoly) / 4096));
}

}  // namespace psx
