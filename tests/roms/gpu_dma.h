/* Helpers for GPU test programs that feed the GPU through DMA channel 2 (psx-spx "DMA Channels",
   "GPU Memory Transfer"): an ordering table cleared by DMA6 (OTC) and sent as a sync mode 2
   linked list, and GP0(A0h)/(C0h) rectangles moved by sync mode 1 blocks with GP1(04h) setting
   the direction. Pixel buffers are word arrays because DMA moves whole words. */
#ifndef GPU_DMA_H
#define GPU_DMA_H
#include "dma_regs.h"
#include "gpu_rom.h"

#define OT_LEN 8
#define DMA_GPU 2
#define DMA_OTC 6

static uint32_t gd_ot[OT_LEN];
static uint32_t gd_pool[512];
static uint32_t gd_pool_used;

static inline void gd_enable(void) { DPCR |= (1u << (DMA_GPU * 4 + 3)) | (1u << (DMA_OTC * 4 + 3)); }

/* DMA6 reverse clear: ot[i] -> &ot[i-1], ot[0] = end marker; the list starts at ot[OT_LEN-1]. */
static inline void gd_clear_ot(void) {
  gd_pool_used = 0;
  D_MADR(DMA_OTC) = PHYS(&gd_ot[OT_LEN - 1]);
  D_BCR(DMA_OTC) = OT_LEN;
  D_CHCR(DMA_OTC) = 0x11000002;
  CHECK_EQ("otc done", dma_wait(DMA_OTC), 1);
}

/* A packet of `n` command words linked in front of slot `slot` (higher slots are sent first). */
static inline uint32_t *gd_packet(int slot, uint32_t n) {
  uint32_t *p = &gd_pool[gd_pool_used];
  gd_pool_used += n + 1;
  p[0] = (n << 24) | (gd_ot[slot] & 0x00FFFFFF);
  gd_ot[slot] = PHYS(p);
  return p + 1;
}

/* Sync mode 2 from the top of the ordering table; MADR ends on the end marker. */
static inline void gd_send_ot(void) {
  GPU_GP1 = 0x04000002; /* DMA direction CPU->GP0 */
  D_MADR(DMA_GPU) = PHYS(&gd_ot[OT_LEN - 1]);
  D_BCR(DMA_GPU) = 0;
  D_CHCR(DMA_GPU) = 0x01000401;
  CHECK_EQ("list done", dma_wait(DMA_GPU), 1);
  CHECK_EQ("list madr at end marker", D_MADR(DMA_GPU), 0x00FFFFFF);
}

/* Block size: the largest of 16, 8, 4, 2, 1 words that divides the transfer. */
static inline uint32_t gd_bcr(uint32_t words) {
  uint32_t bs = 16;
  while (words % bs) bs >>= 1;
  return ((words / bs) << 16) | bs;
}

static inline void gd_block(const void *ram, uint32_t words, uint32_t chcr) {
  D_MADR(DMA_GPU) = PHYS(ram);
  D_BCR(DMA_GPU) = gd_bcr(words);
  D_CHCR(DMA_GPU) = chcr;
  CHECK_EQ("block done", dma_wait(DMA_GPU), 1);
  /* Sync mode 1 advances MADR past the data and counts BA down to 0 (psx-spx). */
  CHECK_EQ("block madr advanced", D_MADR(DMA_GPU), PHYS(ram) + 4 * words);
  CHECK_EQ("block ba zero", D_BCR(DMA_GPU) >> 16, 0);
}

/* CPU->VRAM: GP0(A0h) header by the CPU, the pixels by DMA2 (two per word, low half first). */
static inline void gd_upload(uint32_t x, uint32_t y, uint32_t w, uint32_t h, const uint32_t *pixels) {
  gp0(0x01000000);
  gp0(0xA0000000);
  gp0(XY(x, y));
  gp0(XY(w, h));
  GPU_GP1 = 0x04000002;
  gd_block(pixels, (w * h + 1) / 2, 0x01000201);
}

/* VRAM->CPU: GP0(C0h), then GP1(04h)=3 so the DMA request follows GPUSTAT.27. */
static inline void gd_download(uint32_t x, uint32_t y, uint32_t w, uint32_t h, uint32_t *out) {
  gp0(0xC0000000);
  gp0(XY(x, y));
  gp0(XY(w, h));
  GPU_GP1 = 0x04000003;
  CHECK_EQ("gpustat direction 3", (GPU_STAT >> 29) & 3, 3);
  gd_block(out, (w * h + 1) / 2, 0x01000200);
  GPU_GP1 = 0x04000000;
}

/* Reads up to 64 pixels of one row by DMA into `row`. */
static inline void gd_read_row(uint32_t x, uint32_t y, uint32_t w, uint16_t *row) {
  static uint32_t words[32];
  uint32_t i;
  gd_download(x, y, w, 1, words);
  for (i = 0; i < w; ++i) row[i] = (uint16_t)(words[i / 2] >> (16 * (i & 1)));
}

static inline uint16_t gd_peek(uint32_t x, uint32_t y) {
  uint16_t v;
  gd_read_row(x, y, 1, &v);
  return v;
}

#endif
