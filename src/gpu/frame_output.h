// What the video output shows (psx-spx "GPU Display Control"): the display area of VRAM from
// GP1(05) at the size GP1(06)-(08) select, converted to RGB888 in one contiguous buffer that the
// environment can hand out without copying; 24-bit mode reads three bytes per pixel. Also the
// whole 1024x512 VRAM as RGB888 for debugging views. A renderer drawing at N times the native
// resolution gives an N times larger picture, read from its scaled VRAM; the native picture is
// kept beside it, because save states hold that one (they do not depend on the renderer).
#pragma once
#include <vector>

#include "core/state.h"
#include "core/types.h"
#include "gpu/renderer.h"

namespace psx::gpu {

struct DisplayArea {
  u32 x = 0, y = 0;           // GP1(05) start in VRAM
  u32 width = 320, height = 240;
  bool rgb24 = false;         // GP1(08).4
  bool enabled = false;       // GP1(03)
};

class FrameOutput {
 public:
  static constexpr u32 kMaxWidth = 640;
  static constexpr u32 kMaxHeight = 576;

  FrameOutput();

  // Converts the display area from VRAM (done at each VBlank). A disabled display is black.
  void refresh(const u16* vram, const DisplayArea& area);
  // The same from a renderer, at its scale: 15-bit pictures from the scaled VRAM; 24-bit ones
  // (which scaling cannot improve) and a disabled display are enlarged from the native picture.
  void refresh(const Renderer& renderer, const DisplayArea& area);

  // The picture: native size times the renderer's scale.
  const u8* rgb() const { return scale_ > 1 ? scaled_.data() : rgb_.data(); }
  u32 width() const { return width_ * scale_; }
  u32 height() const { return height_ * scale_; }
  // The native picture, whatever the scale (what save states keep).
  const u8* native_rgb() const { return rgb_.data(); }
  u32 native_width() const { return width_; }
  u32 native_height() const { return height_; }

  // The whole VRAM as 1024x512 RGB888 into `out` (3 MiB).
  static void vram_to_rgb(const u16* vram, u8* out);

  void do_state(StateIO& s);

 private:
  void enlarge();

  std::vector<u8> rgb_;  // native picture
  u32 width_ = 320, height_ = 240;
  u32 scale_ = 1;
  std::vector<u8> scaled_;  // the picture at scale_ > 1
  std::vector<u16> scaled_vram_;
};

}  // namespace psx::gpu
