// The GPU's drawing backend interface. Command processing (gpu.cpp, gp0_commands.cpp) decodes GP0
// words into the primitives below and hands them over whole; a backend owns VRAM and draws. The
// software renderer is the hardware-exact reference; an upscaling OpenGL backend can implement
// the same interface later without touching command processing. Calls are per primitive, never
// per pixel.
#pragma once
#include <algorithm>

#include "core/types.h"
#include "gpu/vram.h"

namespace psx::gpu {

// Drawing environment from GP0(E1)-GP0(E6) plus the interlace field rule, already decoded.
struct DrawState {
  u16 texpage_x = 0;     // E1.0-3 * 64
  u16 texpage_y = 0;     // E1.4 * 256
  u8 semi_mode = 0;      // E1.5-6: 0 B/2+F/2, 1 B+F, 2 B-F, 3 B+F/4
  u8 tex_depth = 0;      // E1.7-8: 0 4-bit CLUT, 1 8-bit CLUT, 2 15-bit direct (3 acts as 2)
  bool dither = false;   // E1.9
  bool flip_x = false;   // E1.12 (rectangles only)
  bool flip_y = false;   // E1.13 (rectangles only)
  bool texture_disable = false;  // E1.11 when GP1(09) allows it
  u8 win_and_u = 0xFF, win_or_u = 0;  // E2: texcoord = (t AND NOT(mask*8)) OR ((offset AND mask)*8)
  u8 win_and_v = 0xFF, win_or_v = 0;
  s32 area_left = 0, area_top = 0, area_right = 0, area_bottom = 0;  // E3/E4, inclusive
  bool set_mask = false;    // E6.0: force bit 15 on drawn pixels
  bool check_mask = false;  // E6.1: do not overwrite pixels whose bit 15 is set
  // 480-line interlace without E1.10 ("draw to display area"): rows of this parity are skipped
  // (the field being displayed); -1 draws every row.
  s32 skip_row_parity = -1;
};

// A vertex after the drawing offset, in VRAM coordinates (11-bit signed range).
struct Vertex {
  s32 x = 0, y = 0;
  u8 r = 0, g = 0, b = 0;
  u8 u = 0, v = 0;
};

struct Triangle {
  Vertex v[3];
  u16 clut_x = 0, clut_y = 0;
  bool shaded = false;    // Gouraud: per-vertex colours interpolated
  bool textured = false;
  bool raw = false;       // raw texture: texel used as is, no modulation
  bool semi = false;      // semi-transparent
};

struct Line {
  Vertex v[2];
  bool shaded = false;
  bool semi = false;
};

struct Rectangle {
  s32 x = 0, y = 0;
  u32 width = 0, height = 0;
  u8 r = 0, g = 0, b = 0;
  u8 u = 0, v = 0;
  u16 clut_x = 0, clut_y = 0;
  bool textured = false;
  bool raw = false;
  bool semi = false;
};

// Mask handling for transfers (GP0(A0), GP0(80)): pixels whose bit 15 is set are kept when
// `check`, and `set` ORs bit 15 into every written pixel (E6 applies to both, psx-spx).
struct MaskMode {
  bool set = false;
  bool check = false;
};

class Renderer {
 public:
  virtual ~Renderer() = default;

  virtual void draw_triangle(const Triangle& t, const DrawState& ds) = 0;
  virtual void draw_line(const Line& l, const DrawState& ds) = 0;
  virtual void draw_rectangle(const Rectangle& r, const DrawState& ds) = 0;
  // GP0(02): x/width already rounded to 16, wraps at the VRAM edges, ignores area and mask.
  virtual void fill(u32 x, u32 y, u32 width, u32 height, u16 pixel) = 0;
  // GP0(80): all coordinates wrap at the VRAM edges.
  virtual void copy(u32 src_x, u32 src_y, u32 dst_x, u32 dst_y, u32 width, u32 height, MaskMode m) = 0;
  // Part of a GP0(A0) transfer: `count` pixels into one row starting at (x, y), wrapping in x.
  virtual void write_row(u32 x, u32 y, const u16* pixels, u32 count, MaskMode m) = 0;
  // The CLUT cache (psx-spx "GP0(01h) Clear Cache"; ps1-tests gpu/clut-cache): 4- and 8-bit
  // textured primitives take their palette from this cache, not from VRAM. The GPU loads it
  // (`count` = 16 or 256 entries from (x, y), wrapping in x) only when a primitive's CLUT or
  // texture depth asks for entries it does not hold (Gpu::clut_load()), before drawing it.
  virtual void load_clut(u32 x, u32 y, u32 count) = 0;
  // The cache's 256 entries, for save states and a change of backend.
  static constexpr u32 kClutEntries = 256;
  const u16* clut_cache() const { return clut_; }
  void set_clut_cache(const u16* entries) { std::copy_n(entries, kClutEntries, clut_); }

  // The current 1024x512 contents (a hardware backend downloads before answering).
  virtual const u16* vram() const = 0;
  // Replaces all of VRAM (save-state load, reset tests).
  virtual void load_vram(const u16* pixels) = 0;
  // The backend's own VRAM when a state load may write it in place (the software renderer's),
  // saving a 1 MiB copy per load; nullptr means load_vram must be used.
  virtual u16* vram_in_place() { return nullptr; }

  // A backend may draw at a multiple of the native resolution (the OpenGL one, 1 to 8); vram()
  // is still the native contents (each N x N block's top-left sub-pixel, the native sample).
  virtual u32 scale() const { return 1; }
  // The native rectangle (x, y, width, height), wrapping at the VRAM edges, at the internal
  // resolution: (width * scale) x (height * scale) pixels into `out`, row by row.
  virtual void read_scaled(u32 x, u32 y, u32 width, u32 height, u16* out) const;

 protected:
  u16 clut_[kClutEntries] = {};
};

}  // namespace psx::gpu
