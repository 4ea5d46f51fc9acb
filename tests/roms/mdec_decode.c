/* MDEC test program: tables and compressed blocks go in through DMA0, pixels come back through
   DMA1; the expected pixels are computed here with the psx-spx algorithm (rl_decode_block,
   real_idct_core, y_to_mono), in integers. */
#include "dma_regs.h"
#include "psx/test.h"

static const uint8_t zigzag[64] = {
    0,  1,  5,  6,  14, 15, 27, 28, 2,  4,  7,  13, 16, 26, 29, 42, 3,  8,  12, 17, 25, 30,
    41, 43, 9,  11, 18, 24, 31, 40, 44, 53, 10, 19, 23, 32, 39, 45, 52, 54, 20, 22, 33, 38,
    46, 51, 55, 60, 21, 34, 37, 47, 50, 56, 59, 61, 35, 36, 48, 49, 57, 58, 62, 63};
static const uint16_t scale[64] = {
    0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x7D8A, 0x6A6D, 0x471C, 0x18F8, 0xE707,
    0xB8E3, 0x9592, 0x8275, 0x7641, 0x30FB, 0xCF04, 0x89BE, 0x89BE, 0xCF04, 0x30FB, 0x7641, 0x6A6D, 0xE707,
    0x8275, 0xB8E3, 0x471C, 0x7D8A, 0x18F8, 0x9592, 0x5A82, 0xA57D, 0xA57D, 0x5A82, 0x5A82, 0xA57D, 0xA57D,
    0x5A82, 0x471C, 0x8275, 0x18F8, 0x6A6D, 0x9592, 0xE707, 0x7D8A, 0xB8E3, 0x30FB, 0x89BE, 0x7641, 0xCF04,
    0xCF04, 0x7641, 0x89BE, 0x30FB, 0x18F8, 0xB8E3, 0x6A6D, 0x8275, 0x7D8A, 0x9592, 0x471C, 0xE707};
static uint8_t quant[64];
static uint32_t words[64];
static uint32_t out[128];
static int32_t blk[64], tmp[64];

static int32_t sx10(uint32_t n) { return (int32_t)((n & 0x3FF) << 22) >> 22; }

static void ref_decode(const uint16_t *src) {
  int zagzig[64];
  for (int i = 0; i < 64; ++i) zagzig[zigzag[i]] = i;
  for (int i = 0; i < 64; ++i) blk[i] = 0;
  uint32_t n = *src++;
  int q = (n >> 10) & 63, k = 0;
  int32_t val = sx10(n) * quant[0];
  for (;;) {
    if (q == 0) val = sx10(n) * 2;
    if (val < -0x400) val = -0x400;
    if (val > 0x3FF) val = 0x3FF;
    blk[q ? zagzig[k] : k] = val;
    n = *src++;
    k += ((n >> 10) & 63) + 1;
    if (k > 63) break;
    val = (sx10(n) * quant[k] * q + 4) / 8;
  }
  int32_t *s = blk, *d = tmp;
  for (int pass = 0; pass < 2; ++pass) {
    for (int x = 0; x < 8; ++x)
      for (int y = 0; y < 8; ++y) {
        int32_t sum = 0;
        for (int z = 0; z < 8; ++z) sum += s[y + z * 8] * ((int16_t)scale[x + z * 8] >> 3);
        d[x + y * 8] = (sum + 0xFFF) >> 13;
      }
    int32_t *t = s;
    s = d;
    d = t;
  }
}

static uint32_t mono(int32_t y) { /* y_to_mono, unsigned */
  y &= 0x1FF;
  if (y & 0x100) y -= 0x200;
  if (y < -128) y = -128;
  if (y > 127) y = 127;
  return (uint32_t)(y ^ 0x80) & 0xFF;
}

/* Sends MDEC command `cmd` with `n` parameter words by DMA0 (blocks of one word). */
static void send(uint32_t cmd, const uint32_t *p, uint32_t n) {
  MDEC0 = cmd;
  D_MADR(0) = PHYS(p);
  D_BCR(0) = (n << 16) | 1;
  D_CHCR(0) = 0x01000201;
  CHECK_EQ("dma0 done", dma_wait(0), 1);
}

static void receive(uint32_t *dst, uint32_t block_words, uint32_t blocks) {
  D_MADR(1) = PHYS(dst);
  D_BCR(1) = (blocks << 16) | block_words;
  D_CHCR(1) = 0x01000200;
}

static void upload_tables(void) {
  for (int i = 0; i < 64; ++i) quant[i] = (uint8_t)(1 + i % 7);
  for (int i = 0; i < 16; ++i)
    words[i] = quant[4 * i] | quant[4 * i + 1] << 8 | quant[4 * i + 2] << 16 | (uint32_t)quant[4 * i + 3] << 24;
  send(0x40000000, words, 16);
  for (int i = 0; i < 32; ++i) words[i] = scale[2 * i] | (uint32_t)scale[2 * i + 1] << 16;
  send(0x60000000, words, 32);
}

static const uint16_t block_y[6] = {(8 << 10) | 40, (0 << 10) | (-13 & 0x3FF), (2 << 10) | 7, (5 << 10) | 100,
                                    0xFE00, 0xFE00};

static void test_mono(void) {
  for (int i = 0; i < 3; ++i) words[i] = block_y[2 * i] | (uint32_t)block_y[2 * i + 1] << 16;
  receive(out, 16, 1);
  send(0x28000003, words, 3); /* MDEC(1), 8-bit, unsigned */
  CHECK_EQ("dma1 done", dma_wait(1), 1);
  CHECK_EQ("dma1 madr end", D_MADR(1), PHYS(out) + 64);
  ref_decode(block_y);
  for (int p = 0; p < 64; ++p) CHECK_EQ("mono pixel", (out[p / 4] >> (8 * (p % 4))) & 0xFF, mono(blk[p]));
  CHECK_EQ("mdec idle", MDEC1 & 0xE000FFFF, 0x8000FFFF);
}

static void test_grey15(void) {
  /* Cr = Cb = 0 gives R = G = B = Y exactly; four flat Y blocks with their own levels. */
  static const int dc[4] = {40, -30, 100, 7};
  uint16_t h[12] = {1 << 10, 0xFE00, 1 << 10, 0xFE00};
  uint32_t level[4];
  for (int b = 0; b < 4; ++b) {
    h[4 + 2 * b] = (uint16_t)((8 << 10) | (dc[b] & 0x3FF));
    h[5 + 2 * b] = 0xFE00;
    ref_decode(&h[4 + 2 * b]);
    level[b] = mono(blk[0]) >> 3;
  }
  for (int i = 0; i < 6; ++i) words[i] = h[2 * i] | (uint32_t)h[2 * i + 1] << 16;
  receive(out, 32, 4);
  send(0x3A000006, words, 6); /* MDEC(1), 15-bit, unsigned, bit 15 set */
  CHECK_EQ("dma1 15bit done", dma_wait(1), 1);
  for (int p = 0; p < 256; ++p) {
    int b = ((p % 16) >= 8) + 2 * ((p / 16) >= 8);
    uint32_t want = level[b] | level[b] << 5 | level[b] << 10 | 0x8000;
    CHECK_EQ("grey pixel", (out[p / 2] >> (16 * (p % 2))) & 0xFFFF, want);
  }
}

int main(void) {
  DPCR |= 0x00000088;
  MDEC1 = 0x80000000;
  CHECK_EQ("mdec reset status", MDEC1, 0x80040000);
  MDEC1 = 0x60000000;
  upload_tables();
  test_mono();
  test_grey15();
  return test_done("mdec_decode");
}
