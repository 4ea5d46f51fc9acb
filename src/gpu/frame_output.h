// What the video output shows (psx-spx "GPU Display Control"): the display area of VRAM from
// GP1(05) at the size GP1(06)-(08) select, converted to RGB888 in one contiguous buffer that the
// environment can hand out without copying; 24-bit mode reads three bytes per pixel. Also the
// whole 1024x512 VRAM as RGB888 for debugging views.
#pragma once
#include <vector>

#include "core/state.h"
#include "core/types.h"

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

  const u8* rgb() const { return rgb_.data(); }
  u32 width() const { return width_; }
  u32 height() const { return height_; }

  // The whole VRAM as 1024x512 RGB888 into `out` (3 MiB).
  static void vram_to_rgb(const u16* vram, u8* out);

  void do_state(StateIO& s);

 private:
  std::vector<u8> rgb_;
  u32 width_ = 320, height_ = 240;
};

}  // namespace psx::gpu
