// Deferred drawing and on-demand frame conversion (see draw_queue.h).
#include "gpu/draw_queue.h"

#include <algorithm>

namespace psx::gpu {
namespace {

// The VRAM a frame of `area` converts (FrameOutput::refresh): 15-bit pixels, or three bytes per
// pixel in 24-bit mode; a disabled display reads nothing.
Rect display_source(const DisplayArea& area) {
  if (!area.enabled) return {};
  const u32 width = std::clamp<u32>(area.width, 1, FrameOutput::kMaxWidth);
  const u32 height = std::clamp<u32>(area.height, 1, FrameOutput::kMaxHeight);
  return wrapped_block(area.x, area.y, area.rgb24 ? (width * 3 + 1) / 2 : width, height);
}

// Rectangles some kept later call may read inside the cover being pruned (no read outside it can
// meet a call that writes only inside it), merged into their bounding box past a few (a superset,
// so the pruning stays on the safe side).
class Readers {
 public:
  Readers() = default;
  explicit Readers(const Rect& cover) : cover_(cover) {}
  void add(const Rect& read) {
    const Rect r{std::max(read.x0, cover_.x0), std::max(read.y0, cover_.y0), std::min(read.x1, cover_.x1),
                 std::min(read.y1, cover_.y1)};
    if (r.empty()) return;
    for (u32 i = 0; i < n_; ++i)
      if (rects_[i].contains(r)) return;
    if (n_ < kMax) {
      rects_[n_++] = r;
      return;
    }
    Rect& m = rects_[kMax - 1];
    m = {std::min(m.x0, r.x0), std::min(m.y0, r.y0), std::max(m.x1, r.x1), std::max(m.y1, r.y1)};
  }
  // Reads inside `cover`, seen from before the call that replaces it, read that call's pixels.
  void forget_inside(const Rect& cover) {
    u32 kept = 0;
    for (u32 i = 0; i < n_; ++i)
      if (!cover.contains(rects_[i])) rects_[kept++] = rects_[i];
    n_ = kept;
  }
  bool read(const Rect& w) const {
    // Rect::intersects without its emptiness tests: add() keeps no empty rectangle.
    if (w.empty()) return false;
    for (u32 i = 0; i < n_; ++i) {
      const Rect& r = rects_[i];
      if (r.x0 < w.x1 && w.x0 < r.x1 && r.y0 < w.y1 && w.y0 < r.y1) return true;
    }
    return false;
  }

 private:
  static constexpr u32 kMax = 16;
  Rect cover_;
  Rect rects_[kMax];
  u32 n_ = 0;
};

// The large covers met so far in prune()'s walk, each with the reads gathered since. None lies
// inside another; past a few, the one met first (the newest call) is let go, which only keeps more.
class Covers {
 public:
  // Whether a call writing `w` is replaced by some cover before anything kept reads it.
  bool replaced(const Rect& w) const {
    for (u32 i = 0; i < n_; ++i)
      if (covers_[i].cover.contains(w) && !covers_[i].readers.read(w)) return true;
    return false;
  }
  void add_read(const Rect& r) {
    for (u32 i = 0; i < n_; ++i) covers_[i].readers.add(r);
  }
  void hide(const Rect& cover) {
    for (u32 i = 0; i < n_; ++i) covers_[i].readers.forget_inside(cover);
  }
  void start(const Rect& cover) {
    u32 kept = 0;
    for (u32 i = 0; i < n_; ++i) {
      if (covers_[i].cover.contains(cover)) return;
      if (!cover.contains(covers_[i].cover)) covers_[kept++] = covers_[i];
    }
    n_ = kept;
    if (n_ == kMax) std::move(covers_ + 1, covers_ + kMax, covers_), --n_;
    covers_[n_++] = {cover, Readers(cover)};
  }

 private:
  struct Gathering {
    Rect cover;
    Readers readers;
  };
  static constexpr u32 kMax = 4;
  Gathering covers_[kMax];
  u32 n_ = 0;
};

}  // namespace

void DrawQueue::set_deferred(bool on) {
  if (!on) flush();
  deferred_ = on;
}

void DrawQueue::triangle(const Triangle& t, const DrawState& ds, u16 clut_load) {
  DrawCommand c;
  c.kind = DrawCommand::Kind::Triangle, c.triangle = t, c.ds = ds, c.clut_load = clut_load;
  push(c);
}

void DrawQueue::quad(const Quad& q, const DrawState& ds, u16 clut_load) {
  DrawCommand c;
  c.kind = DrawCommand::Kind::Quad, c.quad = q, c.ds = ds, c.clut_load = clut_load;
  push(c);
}

void DrawQueue::line(const Line& l, const DrawState& ds) {
  DrawCommand c;
  c.kind = DrawCommand::Kind::Line, c.line = l, c.ds = ds;
  push(c);
}

void DrawQueue::rectangle(const Rectangle& r, const DrawState& ds, u16 clut_load) {
  DrawCommand c;
  c.kind = DrawCommand::Kind::Rectangle, c.rectangle = r, c.ds = ds, c.clut_load = clut_load;
  push(c);
}

void DrawQueue::fill(u32 x, u32 y, u32 width, u32 height, u16 pixel) {
  DrawCommand c;
  c.kind = DrawCommand::Kind::Fill, c.block.x = x, c.block.y = y, c.block.width = width, c.block.height = height;
  c.block.pixel = pixel;
  push(c);
}

void DrawQueue::copy(u32 src_x, u32 src_y, u32 dst_x, u32 dst_y, u32 width, u32 height, MaskMode m) {
  DrawCommand c;
  c.kind = DrawCommand::Kind::Copy, c.block.sx = src_x, c.block.sy = src_y, c.block.x = dst_x, c.block.y = dst_y;
  c.block.width = width, c.block.height = height, c.block.mask = m;
  push(c);
}

void DrawQueue::write_row(u32 x, u32 y, const u16* pixels, u32 count, MaskMode m) {
  DrawCommand c;
  c.kind = DrawCommand::Kind::Row, c.block.x = x, c.block.y = y, c.block.width = count, c.block.mask = m;
  if (!deferred_) {
    // Drawn now: the pixels need not be kept (execute reads them from `pixels`).
    if (frame_pending_ && c.write_rect().intersects(frame_rect_)) convert_frame();
    ++executed_;
    target_->write_row(x, y, pixels, count, m);
    return;
  }
  c.block.pixels = static_cast<u32>(pixels_.size());
  pixels_.insert(pixels_.end(), pixels, pixels + count);
  push(c);
}

void DrawQueue::push(DrawCommand& c) {
  c.write = c.write_rect();
  if (!deferred_) return execute(c, true);
  queue_.push_back(c);
  const size_t n = queue_.size();
  DrawCommand& last = queue_.back();
  using Kind = DrawCommand::Kind;
  if (last.kind == Kind::Quad) {
    last.cover = {};
    if (last.write.area() >= kMinCover) {
      const Triangle second = last.quad.second();  // only for the large quads that may cover
      last.cover = pair_cover({last.quad.first, last.ds}, {second, last.ds});
    }
  } else {
    last.cover = last.overwrite_rect();
  }
  // Two triangles pair up unless a VBlank came between them (its frame sees only the first).
  if (last.kind == Kind::Triangle && n >= 2 && queue_[n - 2].kind == Kind::Triangle &&
      !(frame_pending_ && frame_position_ == n - 1)) {
    DrawCommand& first = queue_[n - 2];
    const Rect a = first.write, b = last.write;
    const Rect bounds{std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
    const Rect pair = bounds.area() >= kMinCover ? pair_cover({first.triangle, first.ds}, {last.triangle, last.ds}) : Rect{};
    if (!pair.empty()) first.cover = pair, first.cover_with_next = true;
  }
  if (queue_.size() < prune_at_ && pixels_.size() < pixels_prune_at_) return;
  prune();
  if (queue_.size() > kMaxCommands / 2 || pixels_.size() > kMaxPixels / 2) draw_all();
  // The next walk after as many calls again as it kept (at least the minimum): each walk drops
  // or keeps every call, so a kept call is walked a bounded number of times on average.
  prune_at_ = std::max(kPruneAt, 2 * queue_.size());
  pixels_prune_at_ = std::max(kPrunePixels, 2 * pixels_.size());
}

Rect DrawQueue::pair_cover(DrawnTriangle first, DrawnTriangle second) {
  if (!may_pair_cover(first, second)) return {};
  PairKey key;
  const DrawnTriangle* pair[2] = {&first, &second};
  for (u32 i = 0; i < 2; ++i) {
    const Triangle& t = pair[i]->t;
    const DrawState& ds = pair[i]->ds;
    for (u32 v = 0; v < 3; ++v) key.xy[6 * i + 2 * v] = t.v[v].x, key.xy[6 * i + 2 * v + 1] = t.v[v].y;
    const s32 state[5] = {ds.area_left, ds.area_top, ds.area_right, ds.area_bottom,
                          t.textured | t.semi << 1 | ds.check_mask << 2 | (ds.skip_row_parity + 1) << 3};
    std::copy(state, state + 5, key.state.begin() + 5 * i);
  }
  for (const PairMemo& m : pair_memo_)
    if (m.used && m.key == key) return m.cover;
  PairMemo& m = pair_memo_[pair_memo_next_++ % pair_memo_.size()];
  m = {key, triangle_pair_cover(first, second), true};
  return m.cover;
}

void DrawQueue::execute(const DrawCommand& c, bool after_frame) {
  if (frame_pending_ && after_frame && c.write.intersects(frame_rect_)) convert_frame();
  using Kind = DrawCommand::Kind;
  const VramBlock& b = c.block;  // read only for the kinds that have one
  ++executed_;
  if (c.clut_load) target_->load_clut(c.clut_x(), c.clut_y(), c.clut_load);
  switch (c.kind) {
    case Kind::Triangle: return target_->draw_triangle(c.triangle, c.ds);
    case Kind::Quad:
      ++executed_;
      target_->draw_triangle(c.quad.first, c.ds);
      return target_->draw_triangle(c.quad.second(), c.ds);
    case Kind::Line: return target_->draw_line(c.line, c.ds);
    case Kind::Rectangle: return target_->draw_rectangle(c.rectangle, c.ds);
    case Kind::Fill: return target_->fill(b.x, b.y, b.width, b.height, b.pixel);
    case Kind::Copy: return target_->copy(b.sx, b.sy, b.x, b.y, b.width, b.height, b.mask);
    case Kind::Row: return target_->write_row(b.x, b.y, pixels_.data() + b.pixels, b.width, b.mask);
    case Kind::ClutLoad: return target_->load_clut(b.x, b.y, b.width);
  }
}

void DrawQueue::flush() {
  // What a walk drops is what no one could see: drawing the rest leaves VRAM the same.
  if (queue_.size() > 1) prune();
  draw_all();
}

void DrawQueue::draw_all() {
  for (size_t i = 0; i < queue_.size(); ++i) execute(queue_[i], i >= frame_position_);
  queue_.clear();
  pixels_.clear();
  frame_position_ = 0;
  prune_at_ = kPruneAt, pixels_prune_at_ = kPrunePixels;
}

void DrawQueue::frame_due(const DisplayArea& area) {
  frame_pending_ = true;
  frame_area_ = area;
  frame_rect_ = display_source(area);
  frame_position_ = queue_.size();
}

void DrawQueue::frame_ready() {
  flush();
  if (frame_pending_) convert_frame();
}

void DrawQueue::convert_frame() {
  output_.refresh(*target_, frame_area_);
  frame_pending_ = false;
}

void DrawQueue::drop() {
  queue_.clear();
  pixels_.clear();
  frame_pending_ = false;
  frame_position_ = 0;
  prune_at_ = kPruneAt, pixels_prune_at_ = kPrunePixels;
}

// Drops every call that writes only inside the cover of a later kept call and that nothing kept
// between them reads. One walk back from the newest call serves every cover: each large cover met
// (kept) starts gathering the reads of the kept calls before it, and the pending frame reads its
// display area at its VBlank. A kept cover also hides the reads inside it from every cover after
// it, since calls before it are seen through its pixels there. A cover inside another one already
// gathering decides nothing the bigger one does not (their reads inside it are the same), and a
// cover around one drops all it would.
//
// The CLUT cache: walking back, `replaced_entries` counts the cache entries (0, 16 or 256) that
// later loads replace before any kept textured call draws with what was there (a textured call
// without a load may draw with all of them). An earlier load of no more entries is dead, and is
// dropped; a dropped call whose load is not leaves it behind, kept (keep_ 2: kept, but no longer
// the call it was), so the cache ends as it would have (save states hold it).
void DrawQueue::prune() {
  keep_.assign(queue_.size(), 1);  // reuses its storage: no allocation per frame
  Covers covers;
  bool frame_added = !frame_pending_;
  bool any_dropped = false;
  u32 replaced_entries = 0;
  for (size_t i = queue_.size(); i-- > 0;) {
    if (!frame_added && i < frame_position_) covers.add_read(frame_rect_), frame_added = true;
    DrawCommand& c = queue_[i];
    const bool load_only = c.kind == DrawCommand::Kind::ClutLoad;
    const u32 load = load_only ? c.block.width : c.clut_load;
    if (load_only ? load <= replaced_entries : covers.replaced(c.write)) {
      keep_[i] = 0, any_dropped = true;
      if (load > replaced_entries) keep_[i] = 2, leave_clut_load(c), covers.add_read(c.reads[0]);
      replaced_entries = std::max(replaced_entries, load);
      continue;
    }
    if (load_only) replaced_entries = std::max(replaced_entries, load);
    if (c.textured()) replaced_entries = load ? std::max(replaced_entries, load) : 0;
    const bool covering = !c.cover.empty() && (!c.cover_with_next || keep_[i + 1] == 1);
    if (covering) covers.hide(c.cover);
    // A kept call is walked again by every later prune: its reads are worked out once.
    if (c.read_count == DrawCommand::kReadsUnknown) c.read_count = static_cast<u8>(c.read_rects(c.reads));
    for (u32 k = 0; k < c.read_count; ++k) covers.add_read(c.reads[k]);
    if (covering && c.cover.area() >= kMinCover) covers.start(c.cover);
  }
  if (any_dropped) compact();
}

// Removes the calls prune() marked, in place: kept calls and their rows' pixels only move towards
// the front, so the vectors keep their storage.
void DrawQueue::compact() {
  size_t out = 0, position = 0;
  u32 pixels_out = 0;
  for (size_t i = 0; i < queue_.size(); ++i) {
    if (!keep_[i]) continue;
    if (i < frame_position_) ++position;
    DrawCommand& c = queue_[i];  // changed in place, then copied once, only if it moves
    if (c.cover_with_next && keep_[i + 1] != 1) c.cover = {}, c.cover_with_next = false;
    if (c.kind == DrawCommand::Kind::Row) {
      VramBlock& b = c.block;
      std::copy(pixels_.begin() + b.pixels, pixels_.begin() + b.pixels + b.width, pixels_.begin() + pixels_out);
      b.pixels = pixels_out;
      pixels_out += b.width;
    }
    if (out != i) queue_[out] = c;
    ++out;
  }
  queue_.resize(out);
  pixels_.resize(pixels_out);
  frame_position_ = position;
}

// Turns a dropped call into the CLUT cache load it made, which reads the CLUT row as it was then.
void DrawQueue::leave_clut_load(DrawCommand& c) {
  VramBlock load;
  load.x = c.clut_x(), load.y = c.clut_y(), load.width = c.clut_load;
  c.kind = DrawCommand::Kind::ClutLoad, c.block = load, c.clut_load = 0;
  c.write = c.cover = {}, c.cover_with_next = false;
  c.read_count = static_cast<u8>(c.read_rects(c.reads));
}

}  // namespace psx::gpu
