// How long the GPU is busy with a drawing command, for GPUSTAT's ready bits (psx-spx "GPU Status
// Register"; ps1-tests gpu/gpustat): bit 26 reads 0 while the GPU draws, bit 28 (and 25 in DMA
// direction 2) while a command waits in the FIFO for the one drawing. The time is a cost per pixel
// drawn, measured on a console by ps1-tests gpu/bandwidth (400 commands over a 320x240 screen,
// timed in HBlanks): the pixels a command covers in the drawing area times that
// cost, booked from the later of now and the end of the previous command. Computed from the
// command's words alone, so it never makes a deferred draw log draw.
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

s64 clipped(s64 x0, s64 y0, s64 x1, s64 y1, const gpu::DrawState& ds) {
  const s64 w = std::min<s64>(x1, ds.area_right + 1) - std::max<s64>(x0, ds.area_left);
  const s64 h = std::min<s64>(y1, ds.area_bottom + 1) - std::max<s64>(y0, ds.area_top);
  return w > 0 && h > 0 ? w * h : 0;
}

// A triangle's pixels: its area, scaled by the part of its bounding box inside the drawing area.
s64 triangle_pixels(const gpu::Vertex& a, const gpu::Vertex& b, const gpu::Vertex& c, const gpu::DrawState& ds) {
  const s64 area2 = std::llabs(s64{b.x - a.x} * (c.y - a.y) - s64{c.x - a.x} * (b.y - a.y));
  const s64 x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
  const s64 y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
  const s64 box = (x1 - x0) * (y1 - y0);
  if (box == 0) return 0;
  return area2 / 2 * clipped(x0, y0, x1, y1, ds) / box;
}
}  // namespace

Cycles Gpu::draw_time(const u32* w) const {
  const u32 c = w[0] >> 24;
  const gpu::DrawState& ds = ds_;
  const bool semi = c & 0x02, textured = c & 0x04;
  s64 pixels = 0, cost = 0;
  switch (c >> 5) {
    case 1: {  // polygon: bit 4 Gouraud, 3 quad, 2 textured
      const bool shaded = c & 0x10;
      const u32 corners = (c & 0x08) ? 4 : 3;
      gpu::Vertex v[4];
      for (u32 k = 0, i = 1; k < corners; ++k) {
        if (shaded && k > 0) ++i;
        set_position(v[k], w[i++]);
        if (textured) ++i;
      }
      pixels = triangle_pixels(v[0], v[1], v[2], ds) + (corners == 4 ? triangle_pixels(v[1], v[2], v[3], ds) : 0);
      cost = textured ? kPolyTextured : semi ? kPolySemi : kPoly;
      break;
    }
    case 2: {  // line (a polyline's first segment; the others come through book_line())
      gpu::Vertex a, b;
      set_position(a, w[1]);
      set_position(b, w[(c & 0x10) ? 3 : 2]);
      pixels = std::max(std::abs(b.x - a.x), std::abs(b.y - a.y)) + 1;
      cost = semi ? kPolySemi : kPoly;
      break;
    }
    case 3: {  // rectangle: bits 3-4 size
      gpu::Vertex p;
      set_position(p, w[1]);
      static constexpr s64 kSizes[4] = {0, 1, 8, 16};
      // Only a variable-size rectangle (size 0) has a width/height word: a 1x1, 8x8 or 16x16 one
      // ends before it (psx-spx "GPU Render Rectangle Commands").
      const u32 size = (c >> 3) & 3, wh = size ? 0 : w[textured ? 3 : 2];
      const s64 width = size ? kSizes[size] : s64{wh & 0x3FF}, height = size ? kSizes[size] : s64{(wh >> 16) & 0x1FF};
      pixels = clipped(p.x, p.y, p.x + width, p.y + height, ds);
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
  return static_cast<Cycles>(pixels * cost / 4096);
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
