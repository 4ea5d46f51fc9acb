/* MDEC test program: tables and compressed blocks go in through DMA0, pixels come back through
   DMA1. The mono block and its expected pixels are ps1-tests' mdec/4bit and mdec/8bit heart block
   and the bytes a real console printed for it (tests/data/ps1-tests/mdec/: heart.mdec,
   4bit-psx.log, 8bit-psx.log; MIT, JaCzekanski); the 15-bit check uses flat blocks whose level
   follows from arithmetic (a DC-only block of value D is D/8 everywhere). */
#include "dma_regs.h"
#include "psx/test.h"

/* psx-spx standard scale table (the one ps1-tests' idct.bin holds). */
static const uint16_t scale[64] = {
    0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x5A82, 0x7D8A, 0x6A6D, 0x471C, 0x18F8, 0xE707,
    0xB8E3, 0x9592, 0x8275, 0x7641, 0x30FB, 0xCF04, 0x89BE, 0x89BE, 0xCF04, 0x30FB, 0x7641, 0x6A6D, 0xE707,
    0x8275, 0xB8E3, 0x471C, 0x7D8A, 0x18F8, 0x9592, 0x5A82, 0xA57D, 0xA57D, 0x5A82, 0x5A82, 0xA57D, 0xA57D,
    0x5A82, 0x471C, 0x8275, 0x18F8, 0x6A6D, 0x9592, 0xE707, 0x7D8A, 0xB8E3, 0x30FB, 0x89BE, 0x7641, 0xCF04,
    0xCF04, 0x7641, 0x89BE, 0x30FB, 0x18F8, 0xB8E3, 0x6A6D, 0x8275, 0x7D8A, 0x9592, 0x471C, 0xE707};
/* ps1-tests quant.bin: the MPEG intra table in zigzag order, for luminance and colour alike. */
static const uint8_t quant[64] = {2,  16, 16, 19, 16, 19, 22, 22, 22, 22, 22, 22, 26, 24, 26, 27,
                                  27, 27, 26, 26, 26, 26, 27, 27, 27, 29, 29, 29, 34, 34, 34, 29,
                                  29, 29, 27, 27, 29, 29, 32, 32, 34, 34, 37, 38, 37, 35, 35, 34,
                                  35, 38, 38, 40, 40, 40, 48, 48, 46, 46, 56, 56, 58, 69, 69, 83};
/* heart.mdec: a DC and 63 AC values, no end code (the block ends at index 63). */
static const uint16_t heart[64] = {
    0x041E, 0x0074, 0x00BD, 0x0393, 0x0024, 0x032B, 0x0015, 0x03F9, 0x03E9, 0x03DA, 0x03EE, 0x03FE, 0x002B,
    0x003F, 0x03C0, 0x03FE, 0x03BE, 0x03FE, 0x03CA, 0x03FD, 0x03F3, 0x03F3, 0x03FD, 0x0007, 0x03D7, 0x0000,
    0x03E0, 0x03F5, 0x0005, 0x0002, 0x03EC, 0x0007, 0x000C, 0x0008, 0x03FE, 0x03F7, 0x03FF, 0x03F9, 0x0001,
    0x03DD, 0x03D8, 0x0009, 0x0016, 0x0001, 0x0013, 0x03CA, 0x0004, 0x03FA, 0x03FC, 0x03FE, 0x0000, 0x0009,
    0x000F, 0x0006, 0x03FE, 0x03FC, 0x03F2, 0x03FA, 0x03F6, 0x0008, 0x03FA, 0x0015, 0x0001, 0x03F5};
/* What the console printed for it: 4-bit (unsigned) and 8-bit (unsigned) output bytes. */
static const uint8_t heart4[32] = {0xf0, 0x0f, 0xff, 0x00, 0xfd, 0xff, 0xff, 0x0f, 0xed, 0xff, 0xff,
                                   0x0f, 0xfb, 0xff, 0xff, 0x0e, 0xf0, 0xff, 0xff, 0x00, 0x00, 0xff,
                                   0x1f, 0x02, 0x31, 0xf2, 0x30, 0x02, 0x41, 0x34, 0x33, 0x11};
static const uint8_t heart8[64] = {
    0x00, 0xff, 0xff, 0x00, 0xff, 0xff, 0x04, 0x00, 0xc9, 0xec, 0xef, 0xed, 0xef, 0xfc, 0xf2, 0x00,
    0xd5, 0xdb, 0xfa, 0xe8, 0xfe, 0xe8, 0xff, 0x00, 0xb7, 0xf3, 0xec, 0xef, 0xeb, 0xff, 0xe3, 0x00,
    0x00, 0xfb, 0xff, 0xf5, 0xf2, 0xff, 0x03, 0x00, 0x00, 0x05, 0xff, 0xfc, 0xff, 0x08, 0x1a, 0x00,
    0x0f, 0x28, 0x1e, 0xff, 0x05, 0x2a, 0x23, 0x00, 0x10, 0x38, 0x40, 0x29, 0x32, 0x32, 0x16, 0x0f};
static uint32_t words[64];
static uint32_t out[128];

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
  for (int i = 0; i < 32; ++i) {
    const uint8_t *q = &quant[(4 * i) & 63];
    words[i] = q[0] | q[1] << 8 | q[2] << 16 | (uint32_t)q[3] << 24;
  }
  send(0x40000001, words, 32); /* MDEC(2), luminance and colour tables */
  for (int i = 0; i < 32; ++i) words[i] = scale[2 * i] | (uint32_t)scale[2 * i + 1] << 16;
  send(0x60000000, words, 32);
}

static void send_heart(uint32_t depth) {
  for (int i = 0; i < 32; ++i) words[i] = heart[2 * i] | (uint32_t)heart[2 * i + 1] << 16;
  send(0x20000000 | depth << 27 | 32, words, 32); /* MDEC(1), unsigned */
}

static void test_heart4(void) {
  receive(out, 8, 1);
  send_heart(0);
  CHECK_EQ("dma1 4bit done", dma_wait(1), 1);
  for (int i = 0; i < 8; ++i)
    CHECK_EQ("4bit word", out[i],
             heart4[4 * i] | heart4[4 * i + 1] << 8 | heart4[4 * i + 2] << 16 | (uint32_t)heart4[4 * i + 3] << 24);
}

static void test_heart8(void) {
  receive(out, 16, 1);
  send_heart(1);
  CHECK_EQ("dma1 8bit done", dma_wait(1), 1);
  /* Every byte as the console printed it (docs/fidelity.md: the IDCT that reproduces mdec/frame). */
  int far = 0, exact = 0;
  for (int p = 0; p < 64; ++p) {
    int d = (int)((out[p / 4] >> (8 * (p % 4))) & 0xFF) - heart8[p];
    far += d < -1 || d > 1;
    exact += d == 0;
  }
  CHECK_EQ("8bit bytes more than one level off", far, 0);
  CHECK_EQ("8bit bytes equal", exact, 64);
  CHECK_EQ("mdec idle", MDEC1 & 0xE000FFFF, 0x8000FFFF);
}

static void test_grey15(void) {
  /* Cr = Cb = 0 gives R = G = B = Y exactly; four flat Y blocks with their own levels: a DC of
     dc * quant[0] = dc * 2 is dc / 4 in every pixel, 5 bits of (dc / 4 + 128) rounded. */
  static const int dc[4] = {20, -16, 48, 4};
  uint16_t h[12] = {1 << 10, 0xFE00, 1 << 10, 0xFE00};
  uint32_t level[4];
  for (int b = 0; b < 4; ++b) {
    h[4 + 2 * b] = (uint16_t)((8 << 10) | (dc[b] & 0x3FF));
    h[5 + 2 * b] = 0xFE00;
    level[b] = (uint32_t)(dc[b] / 4 + 128 + 4) >> 3;
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
  test_heart4();
  test_heart8();
  test_grey15();
  return test_done("mdec_decode");
}
