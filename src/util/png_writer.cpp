// PNG writer: libpng encodes into memory, the project's atomic file writer puts it on disk.
#include "util/png_writer.h"

#include <png.h>

#include <stdexcept>
#include <vector>

#include "core/atomic_file.h"

namespace psx {
namespace {

void append(png_structp png, png_bytep data, png_size_t n) {
  auto* out = static_cast<std::vector<u8>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + n);
}

// libpng reports errors by longjmp; everything that needs cleanup is owned outside this frame.
bool encode(std::vector<u8>& out, png_bytep* rows, u32 width, u32 height, std::string& error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  if (!png) {
    error = "libpng could not start";
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    error = "libpng failed to encode";
    return false;
  }
  png_set_write_fn(png, &out, append, nullptr);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_rows(png, info, rows);
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

bool write_png_rgb(const std::string& path, const u8* rgb, u32 width, u32 height, std::string& error) {
  std::vector<png_bytep> rows(height);
  for (u32 y = 0; y < height; ++y) rows[y] = const_cast<png_bytep>(rgb + size_t{y} * width * 3);
  std::vector<u8> png;
  std::string why;
  if (!encode(png, rows.data(), width, height, why)) {
    error = path + ": " + why;
    return false;
  }
  try {
    write_file_atomically(path, png);
  } catch (const std::runtime_error& e) {
    error = e.what();
    return false;
  }
  return true;
}

}  // namespace psx
