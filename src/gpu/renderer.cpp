// The renderer interface's default for native backends (renderer.h).
#include "gpu/renderer.h"

namespace psx::gpu {

// The native backend's picture is VRAM itself.
void Renderer::read_scaled(u32 x, u32 y, u32 width, u32 height, u16* out) const {
  const u16* v = vram();
  for (u32 row = 0; row < height; ++row)
    for (u32 col = 0; col < width; ++col) *out++ = v[vram_index(x + col, y + row)];
}

}  // namespace psx::gpu
