// PNG files (screenshots, VRAM dumps, recorded frames, learning curves) through libpng: a shared
// utility every layer may use. Files are written to a temporary name and renamed, so a failed
// write never leaves a half-written file.
#pragma once
#include <string>

#include "core/types.h"

namespace psx {

// Writes `width` x `height` RGB888 pixels (rows contiguous). Returns false and sets `error`
// (naming the file) on failure.
bool write_png_rgb(const std::string& path, const u8* rgb, u32 width, u32 height, std::string& error);

}  // namespace psx
