// Deferred drawing and on-demand frames (gpu/draw_queue.h) must be invisible: a GPU that queues
// its drawing ends with the same VRAM, pictures, GPUREAD words and save state as one that draws
// at once (the reference), on random GP0/GP1 streams (the CLUT cache included) and on Tumble
// playing; a queue no one reads stays small; a GPUREAD sees exactly the pixels drawn before it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "core/irq.h"
#include "core/scheduler.h"
#include "gpu/gpu.h"
#include "sanitizer_scale.h"
#include "tumble_console_util.h"

namespace {

using psx::u16;
using psx::u32;
using psx::u64;
using psx::u8;

// One GPU on its own scheduler.
struct Rig {
  psx::Scheduler sched;
  psx::InterruptController irq;
  psx::Gpu gpu{sched, irq};
  u64 vblanks = 0;

  Rig() { gpu.on_vblank = [this] { ++vblanks; }; }

  void gp0(u32 w) { gpu.io_write(0, w, 4); }
  void gp1(u32 w) { gpu.io_write(4, w, 4); }
  u32 read() { return gpu.io_read(0, 4); }
  // Runs to the next VBlank's start.
  void frame() {
    const u64 start = vblanks;
    while (vblanks == start) {
      sched.advance(sched.next_deadline() - sched.now());
      sched.run_due_events();
    }
  }
  std::vector<u8> state() {
    psx::StateIO s;
    gpu.do_state(s);
    return s.buffer();
  }
  std::vector<u8> picture() const {
    const u8* p = gpu.display_rgb();
    return {p, p + size_t{gpu.display_width()} * gpu.display_height() * 3};
  }
};

// The reference draws at once; the other defers, its drawing commands queued as they come
// (draw_log false: the queue's own tests) or first kept in the draw log (gp0_log.cpp). Every word
// goes to both.
struct Twins {
  Rig eager, lazy;
  explicit Twins(bool draw_log = false) {
    lazy.gpu.set_deferred_drawing(true);
    lazy.gpu.set_draw_log(draw_log);
  }
  void gp0(u32 w) { eager.gp0(w), lazy.gp0(w); }
  void gp1(u32 w) { eager.gp1(w), lazy.gp1(w); }
  void frame() { eager.frame(), lazy.frame(); }
};

u32 xy(int x, int y) { return (static_cast<u32>(y) & 0xFFFF) << 16 | (static_cast<u32>(x) & 0xFFFF); }

// Random but valid GP0/GP1 traffic, weighted toward what games send: drawing-mode changes, small
// primitives of every kind, large opaque covers (fills, rectangles, background quads) that let
// the queue prune, transfers, VRAM copies, display changes and VBlanks.
class Stream {
 public:
  explicit Stream(u32 seed) : rng_(seed) {}

  void step(Twins& t, u32& frames, u32& reads) {
    const u32 kind = pick(100);
    if (kind < 8) return t.gp0(0xE1000000 | pick(0x4000));
    if (kind < 10) return t.gp0(0xE2000000 | pick(1u << 20));
    if (kind < 13) return area(t);
    if (kind < 15) return t.gp0(0xE5000000 | pick(64) | pick(64) << 11);
    if (kind < 17) return t.gp0(pick(3) == 0 ? 0x01000000 : 0xE6000000 | (pick(4) == 0 ? pick(4) : 0));
    if (kind < 40) return polygon(t);
    if (kind < 46) return cover(t);
    if (kind < 56) return rectangle(t);
    if (kind < 62) return line(t);
    if (kind < 66) return fill(t);
    if (kind < 69) {
      t.gp0(0x80000000), t.gp0(xy(pick(1024), pick(512))), t.gp0(xy(pick(1024), pick(512)));
      return t.gp0(xy(1 + pick(96), 1 + pick(96)));
    }
    if (kind < 73) return upload(t);
    if (kind < 75) return download(t, reads);
    if (kind < 78) return display(t);
    ++frames;
    t.frame();
  }

 private:
  u32 pick(u32 n) { return std::uniform_int_distribution<u32>(0, n - 1)(rng_); }
  u32 colour() { return pick(1u << 24); }
  u32 vertex() { return xy(static_cast<int>(pick(420)) - 40, static_cast<int>(pick(300)) - 30); }
  // A CLUT attribute: mostly one of a few, as games reuse palettes, so that the CLUT cache is
  // drawn with after fills and uploads rewrote it, across calls the queue drops.
  u32 clut() { return pick(4) == 0 ? pick(1u << 16) : pick(4) * 0x1041; }

  void area(Twins& t) {
    if (pick(2)) {  // a full screen buffer, as games set it
      const u32 y = pick(2) * 240;
      t.gp0(0xE3000000 | y << 10), t.gp0(0xE4000000 | (y + 239) << 10 | 319);
      return;
    }
    t.gp0(0xE3000000 | pick(1u << 19)), t.gp0(0xE4000000 | pick(1u << 19));
  }
  void polygon(Twins& t) {
    const u32 c = 0x20 | pick(32);
    t.gp0(c << 24 | colour());
    const u32 corners = (c & 8) ? 4 : 3;
    for (u32 k = 0; k < corners; ++k) {
      if ((c & 0x10) && k > 0) t.gp0(colour());
      t.gp0(vertex());
      if (c & 4) t.gp0(pick(1u << 16) | (k == 0 ? clut() : k == 1 ? pick(0x1000) : 0) << 16);
    }
  }
  // An opaque untextured cover of the drawing area's usual buffer: a background quad, as
  // Tumble draws its sky, the same as two three-point polygons, or an opaque rectangle.
  void cover(Twins& t) {
    const int y = pick(2) ? 0 : 240;
    const int w = pick(4) == 0 ? 256 : 320, h = 240 - static_cast<int>(pick(2)) * 16;
    const u32 how = pick(4);
    if (how == 0) {
      t.gp0(0x60000000 | colour()), t.gp0(xy(0, y)), t.gp0(xy(w, h));
      return;
    }
    if (how == 1) {
      t.gp0(0x20000000 | colour()), t.gp0(xy(0, y)), t.gp0(xy(w, y)), t.gp0(xy(0, y + h));
      t.gp0(0x20000000 | colour()), t.gp0(xy(w, y)), t.gp0(xy(0, y + h)), t.gp0(xy(w, y + h));
      return;
    }
    const u32 shaded = pick(2) ? 0x10 : 0;
    t.gp0((0x28 | shaded) << 24 | colour()), t.gp0(xy(0, y));
    if (shaded) t.gp0(colour());
    t.gp0(xy(w, y));
    if (shaded) t.gp0(colour());
    t.gp0(xy(0, y + h));
    if (shaded) t.gp0(colour());
    t.gp0(xy(w, y + h));
  }
  void rectangle(Twins& t) {
    const u32 c = 0x60 | pick(32);
    t.gp0(c << 24 | colour()), t.gp0(vertex());
    if (c & 4) t.gp0(pick(1u << 16) | clut() << 16);
    if (((c >> 3) & 3) == 0) t.gp0(xy(pick(200), pick(200)));
  }
  void line(Twins& t) {
    const u32 c = 0x40 | pick(32);
    const bool shaded = c & 0x10;
    t.gp0(c << 24 | colour()), t.gp0(vertex());
    if (shaded) t.gp0(colour());
    t.gp0(vertex());
    if (!(c & 8)) return;
    for (u32 k = pick(4); k > 0; --k) {
      if (shaded) t.gp0(colour());
      t.gp0(vertex());
    }
    t.gp0(0x55555555);
  }
  void fill(Twins& t) {
    t.gp0(0x02000000 | colour());
    if (pick(2)) {
      t.gp0(xy(0, pick(2) * 240)), t.gp0(xy(320, 240));
      return;
    }
    t.gp0(xy(pick(1024), pick(512))), t.gp0(xy(pick(1024), pick(512)));
  }
  void upload(Twins& t) {
    const u32 w = 1 + pick(40), h = 1 + pick(40);
    t.gp0(0xA0000000), t.gp0(xy(pick(1024), pick(512))), t.gp0(xy(w, h));
    for (u32 i = 0; i < (w * h + 1) / 2; ++i) t.gp0(pick(0xFFFFFFFFu));
  }
  void download(Twins& t, u32& reads) {
    const u32 w = 1 + pick(24), h = 1 + pick(24);
    t.gp0(0xC0000000), t.gp0(xy(pick(1024), pick(512))), t.gp0(xy(w, h));
    for (u32 i = 0; i < (w * h + 1) / 2; ++i) {
      const u32 a = t.eager.read(), b = t.lazy.read();
      ASSERT_EQ(a, b) << "GPUREAD word " << i;
    }
    ++reads;
  }
  void display(Twins& t) {
    switch (pick(5)) {
      case 0: return t.gp1(0x05000000 | pick(1024) | pick(512) << 10);
      case 1: return t.gp1(0x08000000 | pick(0x80));
      case 2: return t.gp1(0x03000000 | (pick(4) == 0));
      case 3: {  // GP1(10h): the drawing environment read back (texture window, area, offset)
        if (t.eager.gpu.gpustat() & (1u << 27)) return;  // GPUREAD is a download's
        t.gp1(0x10000002 + pick(4));
        const u32 a = t.eager.read(), b = t.lazy.read();
        ASSERT_EQ(a, b) << "GP1(10h) answer";
        return;
      }
      default: return t.gp1(0x07000000 | 16 | (16 + 1 + pick(300)) << 10);
    }
  }

  std::mt19937 rng_;
};

TEST(GpuDeferred, RandomStreamsEqualEagerDrawing) {
  for (int seed = 1; seed <= test_scale::sized(24, 6); ++seed) {
    SCOPED_TRACE(seed);
    Twins t(seed % 2 == 0);  // the draw log on every other stream
    t.gp1(0x03000000);
    Stream s(seed);
    u32 frames = 0, reads = 0;
    size_t most_queued = 0;
    for (int i = 0; i < 4000; ++i) {
      s.step(t, frames, reads);
      ASSERT_EQ(t.eager.gpu.gpustat(), t.lazy.gpu.gpustat()) << "GPUSTAT at step " << i;
      most_queued = std::max(most_queued, t.lazy.gpu.queued_draws());
      if (i % 500 == 499) {  // a frame request in the middle, sometimes
        ASSERT_EQ(t.eager.picture(), t.lazy.picture()) << "picture at step " << i;
      }
      if (HasFatalFailure()) return;
    }
    EXPECT_GT(most_queued, 0u);  // the lazy GPU did defer
    EXPECT_GT(frames, 0u);
    EXPECT_GT(reads, 0u);
    ASSERT_EQ(t.eager.state(), t.lazy.state());
    ASSERT_EQ(std::memcmp(t.eager.gpu.vram(), t.lazy.gpu.vram(), psx::gpu::kVramPixels * 2), 0);
    ASSERT_EQ(t.eager.picture(), t.lazy.picture());
  }
}

// A frame is VRAM as it was at its VBlank, even when drawing afterwards changes the display
// area before anyone asks (eager and deferred alike).
TEST(GpuDeferred, FrameIsVramAtItsVblank) {
  for (bool deferred : {false, true}) {
    Rig r;
    r.gpu.set_deferred_drawing(deferred);
    r.gp1(0x08000001), r.gp1(0x03000000), r.gp1(0x05000000);
    r.gp0(0x020000F8), r.gp0(xy(0, 0)), r.gp0(xy(320, 240));  // red (0xF8 -> 31) everywhere shown
    r.frame();
    r.gp0(0x0200F800), r.gp0(xy(0, 0)), r.gp0(xy(320, 240));  // green after the VBlank
    const u8* rgb = r.gpu.display_rgb();
    EXPECT_EQ(rgb[0], 255) << deferred;
    EXPECT_EQ(rgb[1], 0) << deferred;
    EXPECT_EQ(r.gpu.vram()[0], 31u << 5) << deferred;  // VRAM itself is green by now
  }
}

// GPUREAD after queued drawing answers with the drawn pixels: a flat opaque rectangle of colour
// (0xF8, 0x10, 0x80) stores 31 | 2 << 5 | 16 << 10 (the top five bits of each channel).
TEST(GpuDeferred, GpureadSeesQueuedDrawing) {
  Rig r;
  r.gpu.set_deferred_drawing(true);
  r.gp0(0xE3000000), r.gp0(0xE4000000 | 511u << 10 | 1023u);
  r.gp0(0x608010F8), r.gp0(xy(100, 50)), r.gp0(xy(8, 4));
  EXPECT_EQ(r.gpu.queued_draws(), 1u);
  r.gp0(0xC0000000), r.gp0(xy(106, 53)), r.gp0(xy(4, 1));
  const u32 pixel = 31u | 2u << 5 | 16u << 10;
  EXPECT_EQ(r.read(), pixel | pixel << 16);  // (106, 53), (107, 53): inside
  EXPECT_EQ(r.read(), 0u);                   // (108, 53), (109, 53): right of it
  EXPECT_EQ(r.gpu.queued_draws(), 0u);
}

// A game that never lets anyone look, ordered as Tumble orders its frames: wait for the VBlank,
// show the buffer drawn last frame, then draw the other one (the one the VBlank's frame showed):
// a full-screen background quad (one call) and 300 small textured triangles, 301 calls a frame.
// A prune in the middle of frame N keeps frame N-2 (the pending frame shows it), frame N-1
// (nothing has covered it yet) and frame N so far: under 4 frames, 4 x 301 calls. The next prune
// comes when the queue has doubled (or reached DrawQueue::kPruneAt), so it never holds more than
// 2 x 4 x 301 calls: far below the cap, so it is pruning, not drawing. Drawing it all gives what
// eager drawing gave.
TEST(GpuDeferred, QueueStaysBoundedWithoutObserver) {
  Twins t;
  t.gp1(0x08000001), t.gp1(0x03000000);
  std::mt19937 rng(7);
  size_t most = 0;
  for (u32 frame = 0; frame < 600; ++frame) {
    const u32 y = (frame & 1) * 240;
    t.frame();
    t.gp1(0x05000000 | (y ^ 240) << 10);
    t.gp0(0xE3000000 | y << 10), t.gp0(0xE4000000 | (y + 239) << 10 | 319), t.gp0(0xE5000000 | y << 11);
    t.gp0(0xE1000200 | 8);  // dither, texture page x 512, 4-bit
    t.gp0(0x38141E5A), t.gp0(xy(0, 0)), t.gp0(0x141E5A), t.gp0(xy(320, 0));
    t.gp0(0x967878), t.gp0(xy(0, 240)), t.gp0(0x967878), t.gp0(xy(320, 240));
    for (u32 i = 0; i < 300; ++i) {
      const int x = static_cast<int>(rng() % 300), yy = static_cast<int>(rng() % 220);
      t.gp0(0x24808080), t.gp0(xy(x, yy)), t.gp0(0x78000000);
      t.gp0(xy(x + 16, yy)), t.gp0(0x00080010), t.gp0(xy(x, yy + 16)), t.gp0(0x1000);
    }
    most = std::max(most, t.lazy.gpu.queued_draws());
  }
  EXPECT_LE(most, 2u * 4 * 301);
  EXPECT_GE(most, psx::gpu::DrawQueue::kPruneAt - 301);  // it waited for a batch
  ASSERT_EQ(t.eager.state(), t.lazy.state());
}

// Queues 1x1 fills at (1000, 500), outside every other call here and read by none, until the
// queue reaches DrawQueue::kPruneAt calls, which prunes it.
void queue_until_prune(Twins& t) {
  for (size_t n = t.lazy.gpu.queued_draws(); n < psx::gpu::DrawQueue::kPruneAt; ++n)
    t.gp0(0x02FFFFFF), t.gp0(xy(1000, 500)), t.gp0(xy(1, 1));
}

// A cover drops an earlier call inside it unless a kept call between them may read what it
// wrote: four VRAM copies read the 16x16 blocks bordering a 16x16 fill at (96, 100) above,
// below, left and right (none of its pixels) and write outside the full-screen fill that
// follows, so at the next prune the small fill goes and the copies, the cover and the padding
// stay.
TEST(GpuDeferred, ReadsBesideADrawingDoNotKeepIt) {
  Twins t;
  t.gp0(0x02FF0000), t.gp0(xy(96, 100)), t.gp0(xy(16, 16));
  const int sources[4][2] = {{96, 84}, {96, 116}, {80, 100}, {112, 100}};
  for (int k = 0; k < 4; ++k)
    t.gp0(0x80000000), t.gp0(xy(sources[k][0], sources[k][1])), t.gp0(xy(600 + 40 * k, 300)), t.gp0(xy(16, 16));
  t.gp0(0x020000FF), t.gp0(xy(0, 0)), t.gp0(xy(320, 240));
  EXPECT_EQ(t.lazy.gpu.queued_draws(), 6u);
  queue_until_prune(t);
  EXPECT_EQ(t.lazy.gpu.queued_draws(), psx::gpu::DrawQueue::kPruneAt - 1);
  ASSERT_EQ(t.eager.state(), t.lazy.state());
}

// A background quad that reaches past the drawing area on every side covers the whole area
// however skewed it is (only its clipped rows count), so the small triangle drawn before it goes
// at the next prune: may_pair_cover() lets through pairs (here the quad's halves) whose off-corner
// vertices all lie outside the area. The quad (-50,-40) (400,-10) (-20,300) (380,280) keeps x <= -20 on its left edge and
// x >= 380 on its right one, and the drawing area is x 0..319, y 0..239.
TEST(GpuDeferred, SkewedQuadPastTheAreaCoversIt) {
  Twins t;
  t.gp0(0xE3000000), t.gp0(0xE4000000 | 239u << 10 | 319), t.gp0(0xE5000000);
  t.gp0(0x20FF00FF), t.gp0(xy(100, 100)), t.gp0(xy(120, 100)), t.gp0(xy(100, 120));
  t.gp0(0x28102030), t.gp0(xy(-50, -40)), t.gp0(xy(400, -10)), t.gp0(xy(-20, 300)), t.gp0(xy(380, 280));
  EXPECT_EQ(t.lazy.gpu.queued_draws(), 2u);  // the triangle and the quad
  queue_until_prune(t);
  EXPECT_EQ(t.lazy.gpu.queued_draws(), psx::gpu::DrawQueue::kPruneAt - 1);
  ASSERT_EQ(t.eager.state(), t.lazy.state());
}

// A quad whose second half spans 1024 or more columns draws only its first half (each half is
// checked on its own): what the queued quad may write still holds that half, so the frame due
// before it, which shows that half's pixels, is converted before the quad is drawn. Vertices
// (500,0) (510,0) (500,10) (-600,10): the second half spans 1110 columns.
TEST(GpuDeferred, QuadWithAHalfTooWideKeepsTheOther) {
  Twins t;
  t.gp1(0x08000001), t.gp1(0x03000000), t.gp1(0x05000000 | 480);
  t.gp0(0xE3000000), t.gp0(0xE4000000 | 511u << 10 | 1023), t.gp0(0xE5000000);
  t.frame();
  t.gp0(0x28FFFFFF), t.gp0(xy(500, 0)), t.gp0(xy(510, 0)), t.gp0(xy(500, 10)), t.gp0(xy(-600, 10));
  EXPECT_EQ(t.lazy.gpu.queued_draws(), 1u);
  for (Rig* r : {&t.eager, &t.lazy}) {
    const std::vector<u8> picture = r->picture();
    ASSERT_EQ(r->gpu.display_width(), 320u);
    const size_t at = 20 * 3;  // (500, 0) is the picture's pixel 20 of row 0: black at the VBlank
    EXPECT_EQ(picture[at] | picture[at + 1] | picture[at + 2], 0);
    EXPECT_EQ(r->gpu.vram()[500], 0x7FFF);  // drawn after it, white
  }
  ASSERT_EQ(t.eager.state(), t.lazy.state());
}

// Two three-point polygons in a row that make a rectangle cover it as a quad would: the small
// triangle drawn before them goes at the next prune.
TEST(GpuDeferred, TwoTrianglesInARowCoverLikeAQuad) {
  Twins t;
  t.gp0(0xE3000000), t.gp0(0xE4000000 | 239u << 10 | 319), t.gp0(0xE5000000);
  t.gp0(0x20FF00FF), t.gp0(xy(100, 100)), t.gp0(xy(120, 100)), t.gp0(xy(100, 120));
  t.gp0(0x20102030), t.gp0(xy(0, 0)), t.gp0(xy(320, 0)), t.gp0(xy(0, 240));
  t.gp0(0x20405060), t.gp0(xy(320, 0)), t.gp0(xy(0, 240)), t.gp0(xy(320, 240));
  EXPECT_EQ(t.lazy.gpu.queued_draws(), 3u);
  queue_until_prune(t);
  EXPECT_EQ(t.lazy.gpu.queued_draws(), psx::gpu::DrawQueue::kPruneAt - 1);
  ASSERT_EQ(t.eager.state(), t.lazy.state());
}

// The queue remembers the last background quads it met (DrawQueue::pair_cover): the same
// positions drawn semi-transparent, textured, under the mask check or in another drawing area
// replace less or nothing, so the small triangles drawn before them must stay. Each variant
// follows the opaque quad that was remembered, and VRAM after it is what eager drawing gave.
TEST(GpuDeferred, RememberedBackgroundQuadsTellVariantsApart) {
  Twins t;
  t.gp1(0x08000001), t.gp1(0x03000000), t.gp1(0x05000000);
  t.gp0(0xE1000200 | 8);  // dither, texture page x 512
  // A four-point polygon over the whole 320x240 screen, of colours `c` and `c` ^ 0x3C3C3C.
  const auto quad = [&](u32 command, u32 c) {
    const bool textured = command & 0x04000000;
    t.gp0(command | c), t.gp0(xy(0, 0));
    if (textured) t.gp0(0x78000000);
    t.gp0(c), t.gp0(xy(320, 0));
    if (textured) t.gp0(0x00080010);
    t.gp0(c ^ 0x3C3C3C), t.gp0(xy(0, 240));
    if (textured) t.gp0(0x1000);
    t.gp0(c ^ 0x3C3C3C), t.gp0(xy(320, 240));
    if (textured) t.gp0(0x1010);
  };
  // Small flat triangles in the top and the bottom half, with the mask bit set (E6h bit 0).
  const auto small = [&](u32 c) {
    t.gp0(0xE6000001);
    for (int i = 0; i < 8; ++i)
      for (int y : {40, 180})
        t.gp0(0x20000000 | c), t.gp0(xy(20 + 30 * i, y)), t.gp0(xy(40 + 30 * i, y)), t.gp0(xy(20 + 30 * i, y + 20));
    t.gp0(0xE6000000);
  };
  constexpr u32 kQuad = 0x38000000;  // shaded four-point polygon, opaque
  const std::vector<std::vector<u32>> variants = {
      {0x3A000000},                                                       // semi-transparent
      {0x3C000000},                                                       // textured (all texels 0)
      {0xE6000002, kQuad, 0xE6000000},                                    // mask check
      {0xE4000000 | 119u << 10 | 1023, kQuad, 0xE4000000 | 511u << 10 | 1023},  // area to row 119
  };
  t.gp0(0xE3000000), t.gp0(0xE4000000 | 511u << 10 | 1023);
  u32 colour = 0x102030;
  for (const auto& variant : variants) {
    quad(kQuad, colour);
    small(colour ^ 0x808080);
    for (u32 w : variant) {
      if ((w >> 24) >= 0x38 && (w >> 24) <= 0x3F) quad(w, colour ^ 0x204060);
      else t.gp0(w);
    }
    // The next variant's opaque quad hides all of this: look now (which draws the queue).
    ASSERT_EQ(std::memcmp(t.eager.gpu.vram(), t.lazy.gpu.vram(), psx::gpu::kVramPixels * 2), 0) << std::hex
                                                                                                 << variant[0];
    colour += 0x182838;
  }
}

// Tumble, playing a level with the console's pixels unobserved, ends every move in the same
// whole save state as with them observed.
TEST(GpuDeferred, TumbleMovesSameStates) {
  using tumble_test::TumbleConsole;
  TumbleConsole seen, unseen;
  unseen.console.set_pixels_observed(false);
  ASSERT_TRUE(seen.start_level(1));
  ASSERT_TRUE(unseen.start_level(1));
  size_t queued = 0, logged = 0;
  const psx::u16 moves[] = {psx::pad_button::kUp, psx::pad_button::kLeft, psx::pad_button::kUp, psx::pad_button::kRight,
                            psx::pad_button::kCross, psx::pad_button::kUp};
  for (psx::u16 m : moves) {
    seen.move(m);
    unseen.move(m);
    queued = std::max(queued, unseen.console.gpu().queued_draws());
    logged = std::max(logged, unseen.console.gpu().logged_draws());
    ASSERT_EQ(seen.console.save_state(false), unseen.console.save_state(false));
  }
  EXPECT_GT(queued, 0u);
  EXPECT_GT(logged, 0u);
  // Left alone, the log fills (no state load drops it) and gives way to the queue, which then
  // stays far below its cap for ten seconds of play (the sky quad prunes); a drawing command is
  // at least 3 words.
  size_t most = 0, most_logged = 0;
  int full_at = -1;
  for (int f = 0; f < 1200 && (full_at < 0 || f < full_at + 600); ++f) {
    unseen.console.run_frame(), seen.console.run_frame();
    const psx::Gpu& gpu = unseen.console.gpu();
    most = std::max(most, gpu.queued_draws() - gpu.logged_draws());
    most_logged = std::max(most_logged, gpu.logged_draws());
    if (full_at < 0 && gpu.logged_draws() == 0) full_at = f;
  }
  EXPECT_GE(full_at, 0);  // it filled within 1200 frames (20 s)
  EXPECT_EQ(unseen.console.gpu().logged_draws(), 0u);
  EXPECT_LE(most_logged, psx::Gpu::kMaxLogWords / 3);
  EXPECT_LT(most, psx::gpu::DrawQueue::kMaxCommands / 4);
  ASSERT_EQ(seen.console.save_state(false), unseen.console.save_state(false));
  const psx::Console::Frame a = seen.console.frame(), b = unseen.console.frame();
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_EQ(std::memcmp(a.rgb, b.rgb, size_t{a.width} * a.height * 3), 0);
}

// The draw log keeps drawing commands as words, so a state load (an environment's reset) drops
// them undecoded: before it every waiting call is a logged one, after it none waits, and the
// states match the eager GPU's loaded alike.
TEST(GpuDrawLog, StateLoadDropsTheLogUndecoded) {
  Twins t(true);
  t.gp1(0x03000000);
  t.gp0(0xE3000000), t.gp0(0xE4000000 | 239u << 10 | 319);
  const std::vector<u8> start = t.eager.state();
  ASSERT_EQ(start, t.lazy.state());
  for (u32 i = 0; i < 50; ++i) {
    t.gp0(0x600000FF | i << 8), t.gp0(xy(static_cast<int>(i) * 4, 10)), t.gp0(xy(8, 8));  // rectangles
    t.gp0(0xE1000000 | (i & 15));                                                          // texture pages
  }
  EXPECT_EQ(t.lazy.gpu.logged_draws(), 50u);
  EXPECT_EQ(t.lazy.gpu.queued_draws(), 50u);
  for (Rig* r : {&t.eager, &t.lazy}) {
    psx::StateIO s(start.data(), start.size());
    r->gpu.do_state(s);
  }
  EXPECT_EQ(t.lazy.gpu.queued_draws(), 0u);
  ASSERT_EQ(t.eager.state(), t.lazy.state());
}

// A filled log (Gpu::kMaxLogWords) is decoded into the queue, which then takes the commands as
// they come until the next state load logs them again; VRAM ends as eager drawing leaves it.
// 1x1 fills of 3 words each, spread over VRAM so that no prune drops them all.
TEST(GpuDrawLog, FullLogGivesWayToTheQueue) {
  Twins t(true);
  const std::vector<u8> start = t.lazy.state();
  u32 n = 0;
  const auto fill = [&] {
    t.gp0(0x02000000 | n), t.gp0(xy(static_cast<int>(n % 1024) & ~15, static_cast<int>(n / 1024 % 512))),
        t.gp0(xy(1, 1));
    ++n;
  };
  while (t.lazy.gpu.logged_draws() < psx::Gpu::kMaxLogWords / 3) fill();
  fill();  // the log's last words: decoded
  EXPECT_EQ(t.lazy.gpu.logged_draws(), 0u);
  fill();
  EXPECT_EQ(t.lazy.gpu.logged_draws(), 0u);  // queued as it came
  EXPECT_GT(t.lazy.gpu.queued_draws(), 0u);
  ASSERT_EQ(std::memcmp(t.eager.gpu.vram(), t.lazy.gpu.vram(), psx::gpu::kVramPixels * 2), 0);
  psx::StateIO s(start.data(), start.size());
  t.lazy.gpu.do_state(s);
  t.lazy.gp0(0x02000000), t.lazy.gp0(xy(0, 0)), t.lazy.gp0(xy(16, 16));
  EXPECT_EQ(t.lazy.gpu.logged_draws(), 1u);  // logged again after the load
}

// In 480-line interlace without GP0(E1).10 a primitive leaves alone the rows of the field shown
// when it comes, so it is decoded at once; with E1.10 set it is logged. Both end as eager drawing.
TEST(GpuDrawLog, FieldRowsAreNotLogged) {
  Twins t(true);
  t.gp1(0x08000024), t.gp1(0x03000000);  // 480-line interlace
  t.gp0(0xE3000000), t.gp0(0xE4000000 | 479u << 10 | 639);
  t.gp0(0xE1000000);
  t.gp0(0x60112233), t.gp0(xy(0, 0)), t.gp0(xy(64, 64));
  EXPECT_EQ(t.lazy.gpu.logged_draws(), 0u);
  t.frame();
  t.gp0(0xE1000400);  // draw to the displayed field too
  t.gp0(0x60445566), t.gp0(xy(32, 32)), t.gp0(xy(64, 64));
  EXPECT_EQ(t.lazy.gpu.logged_draws(), 1u);
  t.frame();
  t.gp0(0xE1000000);
  t.gp0(0x60778899), t.gp0(xy(48, 48)), t.gp0(xy(64, 64));
  EXPECT_EQ(t.lazy.gpu.logged_draws(), 0u);  // the log went to the queue first, in order
  ASSERT_EQ(std::memcmp(t.eager.gpu.vram(), t.lazy.gpu.vram(), psx::gpu::kVramPixels * 2), 0);
  ASSERT_EQ(t.eager.state(), t.lazy.state());
}

}  // namespace
