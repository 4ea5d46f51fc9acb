// PNG files of GPU output (screenshots, VRAM dumps) through libpng. Files are written to a
// temporary name and renamed, so a failed write never leaves a half-written file.
#pragma once
#include <string>

#include "core/types.h"

namespace psx::gpu {

// Writes `width` x `height` RGB888 pixels (rows contiguous). Returns false and sets `error`
// (naming the file) on failure.
bool write_png_rgb(const std::string& path, const u8* rgb, u32 width, u32 height, std::string& error);

}  // namespace psx::gpu
