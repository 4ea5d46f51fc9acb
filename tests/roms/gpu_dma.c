/* GPU through DMA: textures, CLUT and backgrounds are uploaded with DMA2 block mode, every
   primitive family is drawn from one DMA2 linked list built on an OTC-cleared ordering table, and
   every pixel is read back with DMA2 block mode (VRAM->CPU). Expected values are worked out in
   the comments from psx-spx's drawing rules; gpu_polygons.c / gpu_lines_rects.c check the same
   rules through direct GP0 writes. */
#include "gpu_dma.h"

static const uint32_t white_mask = 0x8000 | RGB15(31, 31, 31);
static uint32_t clut_words[3];
static uint32_t page_words[32];
static uint32_t tex15_words[4];
static uint32_t back_words[32];
static uint32_t masked_words[2];

static void upload_assets(void) {
  int i;
  /* 4-bit texture page 10 (x 640), rows 0-15: halfword 0x4321 = texel indices 1,2,3,4. */
  for (i = 0; i < 32; ++i) page_words[i] = 0x43214321;
  gd_upload(640, 0, 4, 16, page_words);
  /* CLUT at (0,480): 0, red, green, blue, white with bit 15 (5 pixels = 3 words). */
  clut_words[0] = RGB15(31, 0, 0) << 16;
  clut_words[1] = RGB15(0, 0, 31) << 16 | RGB15(0, 31, 0);
  clut_words[2] = white_mask;
  gd_upload(0, 480, 5, 1, clut_words);
  /* 15-bit texture row v = 100 of page 10: texel u = 0x0100 + u. */
  for (i = 0; i < 4; ++i) tex15_words[i] = (uint32_t)(0x0101 + 2 * i) << 16 | (0x0100 + 2 * i);
  gd_upload(640, 100, 8, 1, tex15_words);
  /* 8x8 background (20,10,5) under the semi-transparent triangle. */
  for (i = 0; i < 32; ++i) back_words[i] = RGB15(20, 10, 5) << 16 | RGB15(20, 10, 5);
  gd_upload(150, 10, 8, 8, back_words);
  /* Two pixels with the mask bit set inside the fill rectangle. */
  masked_words[0] = (0x8000u | 0x1234u) << 16 | 0x8000u | 0x1234u;
  gd_upload(48, 210, 2, 1, masked_words);
}

static void build_list(void) {
  uint32_t *p;
  gd_clear_ot();
  /* Slot 7 (sent first): a screen-sized Gouraud triangle, then a fill with the drawing area
     shrunk to (0,0)-(99,99) and mask checking on: fill ignores both (psx-spx GP0(02h)). */
  p = gd_packet(7, 13);
  p[0] = 0x300000F8, p[1] = XY(20, 90), p[2] = 0x00F800, p[3] = XY(300, 90), p[4] = 0xF80000;
  p[5] = XY(160, 230);
  p[6] = 0xE3000000, p[7] = 0xE4000000 | (99u << 10) | 99u, p[8] = 0xE6000002;
  p[9] = 0x02604020, p[10] = XY(0x25, 200), p[11] = XY(0x11, 20), p[12] = 0;
  /* Slot 6: environment back to the whole VRAM, then the fill-rule triangle. */
  p = gd_packet(6, 7);
  p[0] = 0xE3000000, p[1] = 0xE4000000 | (511u << 10) | 1023u, p[2] = 0xE6000000;
  p[3] = 0x2000F8F8, p[4] = XY(10, 10), p[5] = XY(18, 10), p[6] = XY(10, 18);
  /* Slot 5: flat quad and Gouraud quad. */
  p = gd_packet(5, 13);
  p[0] = 0x280000F8, p[1] = XY(30, 10), p[2] = XY(38, 10), p[3] = XY(30, 18), p[4] = XY(38, 18);
  p[5] = 0x38000000, p[6] = XY(50, 10), p[7] = 0x00F800, p[8] = XY(81, 10), p[9] = 0;
  p[10] = XY(50, 20), p[11] = 0x00F800, p[12] = XY(81, 20);
  /* Slot 4: raw and modulated 4-bit CLUT textured quads (CLUT id 480<<6, page 10). */
  p = gd_packet(4, 18);
  p[0] = 0x2D000000, p[1] = XY(110, 10), p[2] = (480u << 6 << 16), p[3] = XY(126, 10);
  p[4] = (10u << 16) | 0x10, p[5] = XY(110, 26), p[6] = 0x1000, p[7] = XY(126, 26), p[8] = 0x1010;
  p[9] = 0x2C404040, p[10] = XY(130, 10), p[11] = (480u << 6 << 16), p[12] = XY(146, 10);
  p[13] = (10u << 16) | 0x10, p[14] = XY(130, 26), p[15] = 0x1000, p[16] = XY(146, 26), p[17] = 0x1010;
  /* Slot 3: a line, a Gouraud line, a polyline square and a Gouraud polyline. */
  p = gd_packet(3, 23);
  p[0] = 0x400000F8, p[1] = XY(10, 40), p[2] = XY(20, 40);
  p[3] = 0x50000000, p[4] = XY(50, 42), p[5] = 0x0000F0, p[6] = XY(80, 42);
  p[7] = 0x4800F800, p[8] = XY(90, 40), p[9] = XY(100, 40), p[10] = XY(100, 50), p[11] = XY(90, 50);
  p[12] = XY(90, 40), p[13] = 0x55555555;
  p[14] = 0x58000000, p[15] = XY(110, 40), p[16] = 0xF00000, p[17] = XY(140, 40), p[18] = 0x000000;
  p[19] = XY(140, 70), p[20] = 0x50005000;
  p[21] = 0x68FFFFFF, p[22] = XY(95, 45);
  /* Slot 2: rectangles of each size, a raw 15-bit textured rectangle, the OT-order back square. */
  p = gd_packet(2, 17);
  p[0] = 0x600000F8, p[1] = XY(10, 60), p[2] = XY(5, 3);
  p[3] = 0x6800F800, p[4] = XY(20, 60);
  p[5] = 0x70F80000, p[6] = XY(30, 60);
  p[7] = 0x78F8F8F8, p[8] = XY(40, 60);
  p[9] = 0xE1000000 | 10 | (2 << 7); /* texture page 10, 15-bit */
  p[10] = 0x65000000, p[11] = XY(70, 60), p[12] = (100 << 8), p[13] = XY(8, 1);
  p[14] = 0xE1000000;
  p[15] = 0x78F80000, p[16] = XY(200, 10);
  /* Slot 1: semi-transparent triangle (B/2 + F/2) over the uploaded background. */
  p = gd_packet(1, 4);
  p[0] = 0x22F0A050, p[1] = XY(150, 10), p[2] = XY(158, 10), p[3] = XY(150, 18);
  /* Slot 0 (sent last): green 8x8 over the blue square of slot 2. */
  p = gd_packet(0, 2);
  p[0] = 0x7000F800, p[1] = XY(204, 14);
}

static void check_polygons(void) {
  uint16_t row[40];
  int x, y;
  /* Fill rule: (10,10) (18,10) (10,18) covers 10 <= x < 18 - (y - 10) on rows 10..17. */
  for (y = 9; y < 19; ++y) {
    gd_read_row(9, y, 10, row);
    for (x = 9; x < 19; ++x) {
      int inside = y >= 10 && y < 18 && x >= 10 && x < 18 - (y - 10);
      CHECK_EQ("fill rule", row[x - 9], inside ? RGB15(31, 31, 0) : 0);
    }
  }
  /* Quad (30..37) x (10..17): right and bottom edges excluded. */
  gd_read_row(29, 14, 10, row);
  for (x = 0; x < 10; ++x) CHECK_EQ("flat quad", row[x], (x >= 1 && x <= 8) ? RGB15(31, 0, 0) : 0);
  CHECK_EQ("flat quad bottom", gd_peek(34, 18), 0);
  /* Gouraud: green 0 at x=50 to 248 at x=81, +8 per pixel: 5-bit green = x - 50. */
  gd_read_row(50, 15, 31, row);
  for (x = 0; x < 31; ++x) CHECK_EQ("gouraud quad", row[x], RGB15(0, x, 0));
  /* Textured raw: u = x - 110, colour = clut[(u & 3) + 1]; modulated by 64: 31*64>>7 = 15. */
  static const uint16_t clut[4] = {RGB15(31, 0, 0), RGB15(0, 31, 0), RGB15(0, 0, 31), 0x8000 | RGB15(31, 31, 31)};
  for (y = 10; y < 26; y += 5) {
    gd_read_row(110, y, 16, row);
    for (x = 0; x < 16; ++x) CHECK_EQ("texel", row[x], clut[x & 3]);
  }
  CHECK_EQ("modulated red", gd_peek(130, 12), RGB15(15, 0, 0));
  CHECK_EQ("modulated white", gd_peek(133, 12), 0x8000 | RGB15(15, 15, 15));
  /* (20,10,5) under (80,160,240) = (10,20,30): ((20+10)/2, (10+20)/2, (5+30)/2) = (15,15,17). */
  CHECK_EQ("blend (B+F)/2", gd_peek(151, 11), RGB15(15, 15, 17));
  CHECK_EQ("outside blend", gd_peek(157, 17), RGB15(20, 10, 5));
  /* Big triangle: its first vertex pixel is the first colour, 248 >> 3 = 31. */
  CHECK_EQ("scene corner", gd_peek(20, 90), RGB15(31, 0, 0));
  CHECK_EQ("scene outside", gd_peek(19, 90), 0);
}

static void check_lines(void) {
  uint16_t row[40];
  int i;
  gd_read_row(9, 40, 13, row);
  for (i = 0; i < 13; ++i) CHECK_EQ("line", row[i], (i >= 1 && i <= 11) ? RGB15(31, 0, 0) : 0);
  /* Red 0 -> 240 over 30 steps = 8 per pixel: 5-bit red = step. */
  gd_read_row(50, 42, 31, row);
  for (i = 0; i <= 30; ++i) CHECK_EQ("gouraud line", row[i], RGB15(i, 0, 0));
  CHECK_EQ("polyline top", gd_peek(95, 40), RGB15(0, 31, 0));
  CHECK_EQ("polyline right", gd_peek(100, 45), RGB15(0, 31, 0));
  CHECK_EQ("polyline bottom", gd_peek(95, 50), RGB15(0, 31, 0));
  CHECK_EQ("polyline left", gd_peek(90, 45), RGB15(0, 31, 0));
  CHECK_EQ("after terminator", gd_peek(95, 45), 0x7FFF);
  /* Gouraud polyline: blue 0 -> 240 along (110..140, 40), then 240 -> 0 down to (140, 70). */
  gd_read_row(110, 40, 31, row);
  for (i = 0; i <= 30; ++i) CHECK_EQ("gouraud polyline 1", row[i], RGB15(0, 0, i));
  for (i = 1; i <= 30; ++i) CHECK_EQ("gouraud polyline 2", gd_peek(140, 40 + i), RGB15(0, 0, 30 - i));
}

static void check_rectangles(void) {
  uint16_t row[8];
  int i;
  CHECK_EQ("5x3 corner", gd_peek(14, 62), RGB15(31, 0, 0));
  CHECK_EQ("5x3 right", gd_peek(15, 62), 0);
  CHECK_EQ("5x3 below", gd_peek(14, 63), 0);
  CHECK_EQ("1x1", gd_peek(20, 60), RGB15(0, 31, 0));
  CHECK_EQ("1x1 right", gd_peek(21, 60), 0);
  CHECK_EQ("8x8 corner", gd_peek(37, 67), RGB15(0, 0, 31));
  CHECK_EQ("8x8 outside", gd_peek(38, 67), 0);
  CHECK_EQ("16x16 corner", gd_peek(55, 75), 0x7FFF);
  CHECK_EQ("16x16 outside", gd_peek(55, 76), 0);
  gd_read_row(70, 60, 8, row);
  for (i = 0; i < 8; ++i) CHECK_EQ("textured rect", row[i], 0x0100 + i);
  /* Slot 0 was sent after slot 2, so the green square lies on top of the blue one. */
  CHECK_EQ("ot order back", gd_peek(202, 12), RGB15(0, 0, 31));
  CHECK_EQ("ot order front", gd_peek(206, 16), RGB15(0, 31, 0));
}

static void check_fill(void) {
  /* X 0x25 rounds down to 0x20, width 0x11 up to 0x20: columns 32..63, rows 200..219; colour
     0x604020 -> (0x20>>3, 0x40>>3, 0x60>>3) = (4, 8, 12); the masked pixels are overwritten. */
  const uint32_t c = RGB15(4, 8, 12);
  CHECK_EQ("fill left of x", gd_peek(31, 205), 0);
  CHECK_EQ("fill first column", gd_peek(32, 205), c);
  CHECK_EQ("fill last column", gd_peek(63, 205), c);
  CHECK_EQ("fill right of width", gd_peek(64, 205), 0);
  CHECK_EQ("fill above", gd_peek(40, 199), 0);
  CHECK_EQ("fill last row", gd_peek(40, 219), c);
  CHECK_EQ("fill below", gd_peek(40, 220), 0);
  CHECK_EQ("fill ignores mask", gd_peek(48, 210), c);
  CHECK_EQ("fill ignores mask 2", gd_peek(49, 210), c);
}

static void check_transfers(void) {
  /* An odd-sized 5x3 rectangle (8 words, the last half-word padding) up and back by DMA,
     and the same pixels through the CPU's GPUREAD path. */
  static uint32_t up[8], down[8];
  uint32_t i;
  for (i = 0; i < 8; ++i) up[i] = (0x8000u | (i * 2 + 1) * 0x0421u) << 16 | (i * 2) * 0x0421u;
  up[7] &= 0xFFFF;
  gd_upload(400, 300, 5, 3, up);
  gd_download(400, 300, 5, 3, down);
  for (i = 0; i < 15; ++i) {
    uint32_t expect = (i & 1) ? 0x8000u | i * 0x0421u : i * 0x0421u;
    CHECK_EQ("dma round trip", (down[i / 2] >> (16 * (i & 1))) & 0xFFFF, expect);
    CHECK_EQ("cpu read of dma upload", gpu_peek(400 + i % 5, 300 + i / 5), expect);
  }
}

int main(void) {
  gpu_init();
  gd_enable();
  DICR = 0x00840000; /* master enable + channel 2 */
  I_STAT = 0;
  upload_assets();
  CHECK_EQ("block dicr flag", DICR, 0x84840000);
  CHECK_EQ("block irq3", I_STAT & 8, 8);
  DICR = 0x04840000;
  build_list();
  gd_send_ot();
  CHECK_EQ("list chcr idle", D_CHCR(DMA_GPU), 0x00000401);
  CHECK_EQ("list dicr flag", DICR, 0x84840000);
  DICR = 0;
  check_polygons();
  check_lines();
  check_rectangles();
  check_fill();
  check_transfers();
  return test_done("gpu_dma");
}
