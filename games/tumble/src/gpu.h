/* GPU access (psx-spx "GPU"): display set-up (320x240, NTSC, 15-bit, double-buffered in VRAM rows
   0-239 and 240-479), VRAM uploads, and per-frame ordering tables: primitives are linked into an
   ordering table cleared by DMA channel 6 (OTC) and sent by DMA channel 2 in linked-list mode. */
#ifndef TUMBLE_GPU_H
#define TUMBLE_GPU_H
#include <stdint.h>

#define SCREEN_W 320
#define SCREEN_H 240
#define OT_LEN 512
#define PRIM_WORDS 24576

/* VRAM layout: font (4bpp, 128x64 texels = 32 halfwords wide) at (640,0), its CLUT at (640,64),
   the tile texture (15-bit, 32x32) at (704,0). */
#define FONT_VRAM_X 640
#define FONT_CLUT_Y 64
#define TILE_VRAM_X 704

typedef struct Frame {
  uint32_t ot[OT_LEN];
  uint32_t prims[PRIM_WORDS];
  uint32_t used;
} Frame;

typedef struct Gpu {
  Frame frames[2];
  int draw; /* frame (and VRAM half) being built */
} Gpu;

void gpu_init(Gpu *gpu);
/* Copies w x h halfwords from RAM to VRAM at (x, y) with GP0(A0h), by CPU writes. */
void gpu_upload(int x, int y, int w, int h, const uint16_t *data);
/* Clears the ordering table of the frame being built (DMA 6) and its primitive buffer. */
void gpu_begin(Gpu *gpu);
/* Reserves a primitive of `words` command words and links it into ordering-table slot `z`
   (0 is drawn last); returns the command words, or 0 when the buffer is full. */
uint32_t *gpu_prim(Gpu *gpu, int z, int words);
/* Waits for the previous frame to finish, waits for VBlank, shows it, and starts drawing this
   one by DMA; then swaps buffers. */
void gpu_present(Gpu *gpu);
/* Y of the VRAM half the current frame draws into. */
static inline int gpu_draw_y(const Gpu *gpu) { return gpu->draw * SCREEN_H; }

/* Attribute helpers (psx-spx "GPU Render Polygon/Rectangle Commands"). */
static inline uint32_t gpu_xy(int x, int y) { return ((uint32_t)(y & 0xFFFF) << 16) | (uint32_t)(x & 0xFFFF); }
static inline uint32_t gpu_rgb(int r, int g, int b) { return (uint32_t)r | (uint32_t)g << 8 | (uint32_t)b << 16; }
static inline uint32_t gpu_clut(int x, int y) { return (uint32_t)(x >> 4) | (uint32_t)y << 6; }
/* Texture page: x/64, y/256, colour depth (0 = 4-bit, 2 = 15-bit). */
static inline uint32_t gpu_texpage(int x, int y, int depth) { return (uint32_t)(x >> 6) | (uint32_t)(y >> 8) << 4 | (uint32_t)depth << 7; }

#endif
