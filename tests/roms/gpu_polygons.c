/* Polygons through GP0 writes, read back with GP0(C0h): the top-left fill rule, quads without
   overlap, Gouraud interpolation, dithering, a textured (4-bit CLUT) quad and semi-transparency.
   Expected values are worked out in the comments from psx-spx's rules. */
#include "gpu_rom.h"

static const int dither[4][4] = {{-4, 0, -3, 1}, {2, -2, 3, -1}, {-3, 1, -4, 0}, {3, -1, 2, -2}};

static void fill_rule(void) {
  /* (10,10) (18,10) (10,18): row y covers 10 <= x < 18 - (y - 10); rows 10..17. */
  int x, y;
  uint16_t row[10];
  gp0(0x2000F8F8);
  gp0(XY(10, 10));
  gp0(XY(18, 10));
  gp0(XY(10, 18));
  for (y = 9; y < 19; ++y) {
    gpu_read_pixels(9, y, 10, 1, row);
    for (x = 9; x < 19; ++x) {
      int inside = y >= 10 && y < 18 && x >= 10 && x < 18 - (y - 10);
      CHECK_EQ("fill rule", row[x - 9], inside ? RGB15(31, 31, 0) : 0);
    }
  }
}

static void quad_no_overlap(void) {
  /* Additive (E1 mode 1) colour 8 = 5-bit 1 on black: doubly drawn pixels would read 2. */
  int i;
  uint16_t row[8];
  gp0(0xE1000000 | (1 << 5));
  gp0(0x2A080808);
  gp0(XY(30, 10));
  gp0(XY(38, 10));
  gp0(XY(30, 18));
  gp0(XY(38, 18));
  gpu_read_pixels(30, 14, 8, 1, row);
  for (i = 0; i < 8; ++i) CHECK_EQ("quad", row[i], RGB15(1, 1, 1));
  CHECK_EQ("quad right edge", gpu_peek(38, 14), 0);
  CHECK_EQ("quad bottom edge", gpu_peek(34, 18), 0);
  gp0(0xE1000000);
}

static void gouraud(void) {
  /* Green 0 at x=50 to 248 at x=81: +8 per pixel -> 5-bit green = x - 50. */
  int x;
  uint16_t row[31];
  gp0(0x38000000);
  gp0(XY(50, 10));
  gp0(0x00F800);
  gp0(XY(81, 10));
  gp0(0x000000);
  gp0(XY(50, 20));
  gp0(0x00F800);
  gp0(XY(81, 20));
  gpu_read_pixels(50, 15, 31, 1, row);
  for (x = 0; x < 31; ++x) CHECK_EQ("gouraud", row[x], RGB15(0, x, 0));
}

static void dithered(void) {
  /* Gouraud quad of constant 66 with dither on: (66 + d) >> 3. */
  int x, y;
  uint16_t row[8];
  gp0(0xE1000000 | (1 << 9));
  gp0(0x38424242);
  gp0(XY(90, 10));
  gp0(0x424242);
  gp0(XY(98, 10));
  gp0(0x424242);
  gp0(XY(90, 18));
  gp0(0x424242);
  gp0(XY(98, 18));
  for (y = 10; y < 18; ++y) {
    gpu_read_pixels(90, y, 8, 1, row);
    for (x = 90; x < 98; ++x) {
      uint32_t c = (uint32_t)(66 + dither[y & 3][x & 3]) >> 3;
      CHECK_EQ("dither", row[x - 90], RGB15(c, c, c));
    }
  }
  gp0(0xE1000000);
}

static void textured(void) {
  /* 4-bit page 10 (x 640): texel index = u & 3 + 1 via words 0x4321; CLUT at (0, 480). */
  static const uint16_t page[4] = {0x4321, 0x4321, 0x4321, 0x4321};
  static const uint16_t clut[5] = {0, RGB15(31, 0, 0), RGB15(0, 31, 0), RGB15(0, 0, 31), 0x8000 | RGB15(31, 31, 31)};
  int i, j;
  uint16_t row[16];
  for (j = 0; j < 16; ++j) gpu_write_pixels(640, j, 4, 1, page);
  gpu_write_pixels(0, 480, 5, 1, clut);
  /* Raw textured quad 16x16 at (110,10), u = x - 110: pixel colour = clut[(u & 3) + 1]. */
  gp0(0x2D000000);
  gp0(XY(110, 10));
  gp0((480u << 6 << 16) | 0x0000);
  gp0(XY(126, 10));
  gp0((10u << 16) | 0x0010);
  gp0(XY(110, 26));
  gp0(0x1000);
  gp0(XY(126, 26));
  gp0(0x1010);
  for (j = 0; j < 16; j += 5) {
    gpu_read_pixels(110, 10 + j, 16, 1, row);
    for (i = 0; i < 16; ++i) CHECK_EQ("texel", row[i], clut[(i & 3) + 1]);
  }
  /* Modulated by 0x40 (half): (31 * 64) >> 7 = 15. */
  gp0(0x2C404040);
  gp0(XY(130, 10));
  gp0((480u << 6 << 16) | 0x0000);
  gp0(XY(146, 10));
  gp0((10u << 16) | 0x0010);
  gp0(XY(130, 26));
  gp0(0x1000);
  gp0(XY(146, 26));
  gp0(0x1010);
  CHECK_EQ("modulated red", gpu_peek(130, 12), RGB15(15, 0, 0));
  CHECK_EQ("modulated white", gpu_peek(133, 12), 0x8000 | RGB15(15, 15, 15));
}

static void semi_transparent(void) {
  /* Background (20,10,5) under colour (80,160,240) = (10,20,30), mode 0: (15,15,17). */
  uint16_t back[64];
  int i;
  for (i = 0; i < 64; ++i) back[i] = RGB15(20, 10, 5);
  gpu_write_pixels(150, 10, 8, 8, back);
  gp0(0x22F0A050);
  gp0(XY(150, 10));
  gp0(XY(158, 10));
  gp0(XY(150, 18));
  CHECK_EQ("blend (B+F)/2", gpu_peek(151, 11), RGB15(15, 15, 17));
  CHECK_EQ("outside blend", gpu_peek(157, 17), RGB15(20, 10, 5));
}

static void big_scene(void) {
  /* A screen-sized Gouraud triangle with red, green and blue corners (look at the screenshot);
     the top-left corner pixel is the first vertex's colour exactly: 248 >> 3 = 31. */
  gp0(0x300000F8);
  gp0(XY(20, 60));
  gp0(0x00F800);
  gp0(XY(300, 60));
  gp0(0xF80000);
  gp0(XY(160, 230));
  CHECK_EQ("scene corner", gpu_peek(20, 60), RGB15(31, 0, 0));
  CHECK_EQ("scene outside", gpu_peek(19, 60), 0);
}

int main(void) {
  gpu_init();
  big_scene();
  fill_rule();
  quad_no_overlap();
  gouraud();
  dithered();
  textured();
  semi_transparent();
  return test_done("gpu_polygons");
}
