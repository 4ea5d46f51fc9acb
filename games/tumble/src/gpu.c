/* GPU set-up, VRAM uploads and the ordering-table frame loop (see gpu.h). */
#include "gpu.h"
#include "hw.h"

/* Waits for a GPUSTAT bit; returns 0 if it never came (a GPU that does not answer must not hang
   the game). */
static int gpu_wait(uint32_t bit) {
  for (uint32_t spin = 0; spin < 100000u; ++spin)
    if (GPU_STAT & bit) return 1;
  return 0;
}

static void gp0_wait(void) { gpu_wait(GPUSTAT_READY_CMD); }

static void gp1(uint32_t cmd) { GPU_GP1 = cmd; }

void gpu_init(Gpu *gpu) {
  gp1(0x00000000);                  /* GP1(00h) reset */
  gp1(0x06000000 | 0x260 | (0x260 + SCREEN_W * 8) << 12); /* GP1(06h) horizontal range, 320 dots x 8 */
  gp1(0x07000000 | 16 | (16 + SCREEN_H) << 10);           /* GP1(07h) vertical range, NTSC lines 16..256 */
  gp1(0x08000001);                  /* GP1(08h) 320 wide, 240 lines, NTSC, 15-bit, progressive */
  gp1(0x05000000);                  /* GP1(05h) display from VRAM (0,0) */
  gpu->draw = 0;
  gpu->frames[0].used = gpu->frames[1].used = 0;
}

void gpu_upload(int x, int y, int w, int h, const uint16_t *data) {
  /* The words go by CPU writes, not DMA: direction off, and each word waits for GPUSTAT.28 (ready
     to receive a DMA block, whatever the direction; psx-spx "GPU Status Register"), as the SDKs'
     uploads do. GPUSTAT.25 means "FIFO not full" only in direction 1, which some emulators never
     set there, dropping every glyph. */
  gp1(0x04000000);                  /* GP1(04h) DMA direction off */
  gp0_wait();
  GPU_GP0 = 0x01000000;             /* GP0(01h) clear texture cache */
  gp0_wait();
  GPU_GP0 = 0xA0000000;             /* GP0(A0h) copy rectangle CPU to VRAM */
  GPU_GP0 = gpu_xy(x, y);
  GPU_GP0 = gpu_xy(w, h);
  uint32_t words = ((uint32_t)w * (uint32_t)h + 1) / 2;
  for (uint32_t i = 0; i < words; ++i) {
    if (!gpu_wait(GPUSTAT_READY_DMA)) return;
    uint32_t lo = data[2 * i];
    uint32_t hi = 2 * i + 1 < (uint32_t)w * (uint32_t)h ? data[2 * i + 1] : 0;
    GPU_GP0 = lo | hi << 16;
  }
  gp0_wait();
}

void gpu_begin(Gpu *gpu) {
  Frame *f = &gpu->frames[gpu->draw];
  f->used = 0;
  /* OTC fills backwards from the address given: slot i links to slot i-1, slot 0 ends the list
     with FFFFFFh (psx-spx "DMA channel 6 OTC"). */
  DMA_MADR(DMA_OTC) = (uint32_t)&f->ot[OT_LEN - 1] & 0xFFFFFF;
  DMA_BCR(DMA_OTC) = OT_LEN;
  DMA_CHCR(DMA_OTC) = 0x11000002;   /* start + trigger, backwards */
  hw_wait_dma(DMA_OTC);
}

uint32_t *gpu_prim(Gpu *gpu, int z, int words) {
  Frame *f = &gpu->frames[gpu->draw];
  if (f->used + (uint32_t)words + 1 > PRIM_WORDS) return 0;
  if (z < 0) z = 0;
  if (z >= OT_LEN) z = OT_LEN - 1;
  uint32_t *p = &f->prims[f->used];
  f->used += (uint32_t)words + 1;
  /* Packet header: word count in bits 24-31, next packet's address in bits 0-23. */
  p[0] = (uint32_t)words << 24 | (f->ot[z] & 0xFFFFFF);
  f->ot[z] = (uint32_t)p & 0xFFFFFF;
  return p + 1;
}

static void draw_environment(Gpu *gpu) {
  int y = gpu_draw_y(gpu);
  /* Linked into the last slot so it is the first packet the DMA walks. */
  uint32_t *p = gpu_prim(gpu, OT_LEN - 1, 4);
  if (!p) return;
  p[0] = 0xE3000000 | (uint32_t)y << 10;                                /* drawing area top-left */
  p[1] = 0xE4000000 | (uint32_t)(y + SCREEN_H - 1) << 10 | (SCREEN_W - 1); /* bottom-right */
  p[2] = 0xE5000000 | (uint32_t)y << 11;                                /* drawing offset */
  p[3] = 0xE1000000 | 0x200 | gpu_texpage(TILE_VRAM_X, 0, 2);           /* dither, tile page */
}

void gpu_present(Gpu *gpu) {
  Frame *f = &gpu->frames[gpu->draw];
  draw_environment(gpu);
  hw_wait_dma(DMA_GPU);
  gp0_wait();
  hw_wait_vblank();
  gp1(0x05000000 | (uint32_t)(gpu_draw_y(gpu) ^ SCREEN_H) << 10); /* show the finished half */
  gp1(0x03000000);                                                /* display on */
  gp1(0x04000002);                                                /* DMA direction CPU to GP0 */
  DMA_MADR(DMA_GPU) = (uint32_t)&f->ot[OT_LEN - 1] & 0xFFFFFF;
  DMA_BCR(DMA_GPU) = 0;
  DMA_CHCR(DMA_GPU) = 0x01000401;   /* start, linked-list mode, from RAM */
  gpu->draw ^= 1;
}
