// Drawing and frame conversion on demand. Every renderer call of the GPU passes through here.
//
// Frames: at each VBlank the GPU only notes the display area (frame_due); the picture is
// converted when someone asks for it (frame_ready), or earlier, just before a drawing call would
// change a pixel it shows, so it is always VRAM as it was at that VBlank.
//
// Deferred drawing (set_deferred(true), for when nothing looks at pixels): calls are kept in
// order instead of drawn, and drawn exactly as they would have been when anything needs VRAM
// (flush). To keep the queue small when nothing ever looks, a call that surely replaces a large
// rectangle (a GP0(02) fill, an opaque untextured rectangle, or an opaque untextured quad or two
// such triangles in a row that together cover a rectangle, like a full-screen background quad)
// drops every earlier call that writes only inside it, unless a later kept call, or the frame
// due, may read what it wrote. A dropped call that loads the CLUT cache leaves that load behind
// (DrawCommand::Kind::ClutLoad) unless a later kept call loads it again before drawing with it.
// The queue is pruned so in batches, once it has grown by as many calls as the last prune kept
// (at least kPruneAt), and before it is drawn. Past a size cap the queue is drawn.
#pragma once
#include <array>
#include <vector>

#include "gpu/draw_command.h"
#include "gpu/frame_output.h"
#include "gpu/renderer.h"

namespace psx::gpu {

class DrawQueue {
 public:
  // A prune that keeps more than half of these draws the queue (bounds the memory of a queue no
  // one looks at).
  static constexpr size_t kMaxCommands = 16384;
  static constexpr size_t kMaxPixels = 256 * 1024;  // GP0(A0) pixels kept
  // The least growth between prunes, in calls and in GP0(A0) pixels. A prune walks the whole
  // queue, and a frame's calls stay until a later frame's cover (two frames later with double
  // buffering, more while a pending frame shows them): batches of many frames walk each call
  // about once or twice instead of once per frame it stays.
  static constexpr size_t kPruneAt = 2048;
  static constexpr size_t kPrunePixels = 64 * 1024;
  // Covers smaller than this drop nothing (each one the walk keeps checks every earlier call); a
  // full-screen clear is 320x240 or more.
  static constexpr s64 kMinCover = 128 * 128;

  explicit DrawQueue(FrameOutput& output) : output_(output) {}

  void set_target(Renderer* target) { target_ = target; }
  // Off draws everything queued first.
  void set_deferred(bool on);
  bool deferred() const { return deferred_; }
  size_t size() const { return queue_.size(); }
  // The calls made to the renderer so far, each of which may have changed VRAM.
  u64 executed() const { return executed_; }

  // `clut_load`: the CLUT cache entries loaded from the primitive's CLUT before it is drawn (0,
  // 16 or 256; Renderer::load_clut()).
  void triangle(const Triangle& t, const DrawState& ds, u16 clut_load);
  // A four-point polygon: the renderer draws the triangles q.first and q.second(). Queued as one
  // call, which the queue's walks meet once (three quarters of Tumble's polygons are quads).
  void quad(const Quad& q, const DrawState& ds, u16 clut_load);
  void line(const Line& l, const DrawState& ds);
  void rectangle(const Rectangle& r, const DrawState& ds, u16 clut_load);
  void fill(u32 x, u32 y, u32 width, u32 height, u16 pixel);
  void copy(u32 src_x, u32 src_y, u32 dst_x, u32 dst_y, u32 width, u32 height, MaskMode m);
  void write_row(u32 x, u32 y, const u16* pixels, u32 count, MaskMode m);

  // Draws everything queued, in order.
  void flush();
  // The frame of this VBlank shows `area` of VRAM as it is now.
  void frame_due(const DisplayArea& area);
  // Makes the frame due (if any) the output's picture.
  void frame_ready();
  // Forgets the queue and the frame due (VRAM and the picture are being replaced: state load).
  void drop();

 private:
  void push(DrawCommand& c);  // fills in c.write, then draws c or queues a copy
  void execute(const DrawCommand& c, bool after_frame);
  void draw_all();  // flush() without the prune
  void convert_frame();
  void prune();
  void leave_clut_load(DrawCommand& c);
  void compact();
  // triangle_pair_cover() for the pairs may_pair_cover() lets through (a large quad's halves, or
  // two large triangles in a row), through a memo of the last 32 met, by all it depends on (the
  // vertices' positions, the flags that let a triangle keep old pixels, the drawing areas): a
  // game draws the same background quad every frame, and walking its rows costs more than the
  // rest of its queueing. (Measured while quads were queued as two triangles, when pairs of a
  // small triangle and a quad's half pushed the quad out of smaller memos: Tumble's pairs cost
  // 97 M host instructions in 100 moves without a memo, 31 M with 16 entries.)
  Rect pair_cover(DrawnTriangle first, DrawnTriangle second);
  struct PairKey {
    std::array<s32, 12> xy{};     // both triangles' vertices
    std::array<s32, 10> state{};  // per triangle: its area (4), then textured, semi, check_mask, row parity
    bool operator==(const PairKey&) const = default;
  };
  struct PairMemo {
    PairKey key;
    Rect cover;
    bool used = false;
  };
  std::array<PairMemo, 32> pair_memo_{};
  size_t pair_memo_next_ = 0;

  FrameOutput& output_;
  Renderer* target_ = nullptr;
  bool deferred_ = false;
  u64 executed_ = 0;
  std::vector<DrawCommand> queue_;
  std::vector<u16> pixels_;  // the kept GP0(A0) rows' pixels
  std::vector<u8> keep_;     // prune()'s verdict per queued call
  size_t prune_at_ = kPruneAt;  // queue_.size() that starts the next prune
  size_t pixels_prune_at_ = kPrunePixels;
  // The frame not yet converted: its area, the VRAM it reads, and how many queued calls came
  // before its VBlank.
  bool frame_pending_ = false;
  DisplayArea frame_area_;
  Rect frame_rect_;
  size_t frame_position_ = 0;
};

}  // namespace psx::gpu
