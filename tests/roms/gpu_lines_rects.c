/* Lines, polylines and rectangles through GP0 writes, read back with GP0(C0h): end points,
   Gouraud lines, the 5xxx5xxx polyline terminator, rectangle sizes, textured rectangles with
   flip, and the four semi-transparency equations. Expected values from psx-spx's rules. */
#include "gpu_rom.h"

static void lines(void) {
  int i;
  uint16_t row[32];
  /* Horizontal, both end points drawn. */
  gp0(0x400000F8);
  gp0(XY(10, 40));
  gp0(XY(20, 40));
  gpu_read_pixels(9, 40, 13, 1, row);
  for (i = 0; i < 13; ++i) CHECK_EQ("line", row[i], (i >= 1 && i <= 11) ? RGB15(31, 0, 0) : 0);
  /* Diagonal, right to left. */
  gp0(0x40F80000);
  gp0(XY(40, 40));
  gp0(XY(30, 50));
  for (i = 0; i <= 10; ++i) CHECK_EQ("diagonal", gpu_peek(40 - i, 40 + i), RGB15(0, 0, 31));
  /* Gouraud: red 0 -> 240 over 30 steps = 8 per pixel: 5-bit red = step. */
  gp0(0x50000000);
  gp0(XY(50, 42));
  gp0(0x0000F0);
  gp0(XY(80, 42));
  gpu_read_pixels(50, 42, 31, 1, row);
  for (i = 0; i <= 30; ++i) CHECK_EQ("gouraud line", row[i], RGB15(i, 0, 0));
  /* Polyline: a square outline, then the terminator; the next command must work. */
  gp0(0x4800F800);
  gp0(XY(90, 40));
  gp0(XY(100, 40));
  gp0(XY(100, 50));
  gp0(XY(90, 50));
  gp0(XY(90, 40));
  gp0(0x55555555);
  gp0(0x68FFFFFF);
  gp0(XY(95, 45));
  CHECK_EQ("polyline top", gpu_peek(95, 40), RGB15(0, 31, 0));
  CHECK_EQ("polyline right", gpu_peek(100, 45), RGB15(0, 31, 0));
  CHECK_EQ("polyline bottom", gpu_peek(95, 50), RGB15(0, 31, 0));
  CHECK_EQ("polyline left", gpu_peek(90, 45), RGB15(0, 31, 0));
  CHECK_EQ("after terminator", gpu_peek(95, 45), 0x7FFF);
}

static void rectangles(void) {
  gp0(0x600000F8); /* variable 5x3 */
  gp0(XY(10, 60));
  gp0(XY(5, 3));
  gp0(0x6800F800); /* 1x1 */
  gp0(XY(20, 60));
  gp0(0x70F80000); /* 8x8 */
  gp0(XY(30, 60));
  gp0(0x78F8F8F8); /* 16x16 */
  gp0(XY(40, 60));
  CHECK_EQ("5x3 corner", gpu_peek(14, 62), RGB15(31, 0, 0));
  CHECK_EQ("5x3 right", gpu_peek(15, 62), 0);
  CHECK_EQ("5x3 below", gpu_peek(14, 63), 0);
  CHECK_EQ("1x1", gpu_peek(20, 60), RGB15(0, 31, 0));
  CHECK_EQ("1x1 right", gpu_peek(21, 60), 0);
  CHECK_EQ("8x8 corner", gpu_peek(37, 67), RGB15(0, 0, 31));
  CHECK_EQ("8x8 outside", gpu_peek(38, 67), 0);
  CHECK_EQ("16x16 corner", gpu_peek(55, 75), 0x7FFF);
  CHECK_EQ("16x16 outside", gpu_peek(55, 76), 0);
}

static void textured_flip(void) {
  /* 15-bit page 10 (x 640), row v = 100: texel u = 0x0100 + u. */
  uint16_t tex[8], row[8];
  int i;
  for (i = 0; i < 8; ++i) tex[i] = (uint16_t)(0x0100 + i);
  gpu_write_pixels(640, 100, 8, 1, tex);
  gp0(0xE1000000 | 10 | (2 << 7));
  gp0(0x65000000); /* raw textured 8x1 from u = 0 */
  gp0(XY(70, 60));
  gp0((100 << 8) | 0);
  gp0(XY(8, 1));
  gpu_read_pixels(70, 60, 8, 1, row);
  for (i = 0; i < 8; ++i) CHECK_EQ("textured rect", row[i], 0x0100 + i);
  gp0(0xE1000000 | 10 | (2 << 7) | (1 << 12)); /* X flip: u = 7, 6, ... 0 */
  gp0(0x65000000);
  gp0(XY(70, 61));
  gp0((100 << 8) | 7);
  gp0(XY(8, 1));
  gpu_read_pixels(70, 61, 8, 1, row);
  for (i = 0; i < 8; ++i) CHECK_EQ("flipped rect", row[i], 0x0107 - i);
  gp0(0xE1000000);
}

static void blend_modes(void) {
  /* Background (20,10,5), foreground (80,160,240) = (10,20,30) on 5-bit channels. */
  static const uint32_t expected[4] = {RGB15(15, 15, 17), RGB15(30, 30, 31), RGB15(10, 0, 0), RGB15(22, 15, 12)};
  uint16_t back[64];
  uint32_t mode;
  int i;
  for (i = 0; i < 64; ++i) back[i] = RGB15(20, 10, 5);
  for (mode = 0; mode < 4; ++mode) {
    gpu_write_pixels(90 + mode * 10, 60, 8, 8, back);
    gp0(0xE1000000 | (mode << 5));
    gp0(0x72F0A050); /* 8x8 semi-transparent */
    gp0(XY(90 + mode * 10, 60));
    CHECK_EQ("blend mode", gpu_peek(93 + mode * 10, 63), expected[mode]);
  }
  gp0(0xE1000000);
}

int main(void) {
  gpu_init();
  lines();
  rectangles();
  textured_flip();
  blend_modes();
  return test_done("gpu_lines_rects");
}
