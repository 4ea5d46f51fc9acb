// PNG writer (libpng), atomic via temp file + rename.
#include "gpu/png_writer.h"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <vector>

namespace psx::gpu {
namespace {

// libpng reports errors by longjmp; everything that needs cleanup is owned outside this frame.
bool encode(FILE* f, png_bytep* rows, u32 width, u32 height, std::string& error) {
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
  png_init_io(png, f);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_rows(png, info, rows);
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

bool write_png_rgb(const std::string& path, const u8* rgb, u32 width, u32 height, std::string& error) {
  std::string tmp = path + ".tmp";
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) {
    error = path + ": cannot create " + tmp + ": " + std::strerror(errno);
    return false;
  }
  std::vector<png_bytep> rows(height);
  for (u32 y = 0; y < height; ++y) rows[y] = const_cast<png_bytep>(rgb + size_t{y} * width * 3);
  std::string why;
  bool ok = encode(f, rows.data(), width, height, why);
  if (std::fclose(f) != 0 && ok) {
    ok = false;
    why = std::strerror(errno);
  }
  std::error_code ec;
  if (ok) std::filesystem::rename(tmp, path, ec);
  if (!ok || ec) {
    error = path + ": " + (ok ? ec.message() : why);
    std::filesystem::remove(tmp, ec);
    return false;
  }
  return true;
}

}  // namespace psx::gpu
