/* Helpers for the GPU test programs: GP0/GP1 port writes, display set-up, and pixel read-back
   through GP0(C0h) VRAM->CPU transfers (psx-spx "GPU I/O Ports", "GPU Memory Transfer"). */
#ifndef GPU_ROM_H
#define GPU_ROM_H
#include <stdint.h>

#include "psx/test.h"

#define GPU_GP0 (*(volatile uint32_t *)0xBF801810)
#define GPU_GP1 (*(volatile uint32_t *)0xBF801814)
#define GPU_READ GPU_GP0
#define GPU_STAT GPU_GP1

#define XY(x, y) ((((uint32_t)(y) & 0xFFFF) << 16) | ((uint32_t)(x) & 0xFFFF))
#define RGB15(r, g, b) ((uint32_t)(r) | ((uint32_t)(g) << 5) | ((uint32_t)(b) << 10))

/* Bound on the polls of a GPUSTAT ready bit; the GPU answers within a few commands' time. */
#define GPU_WAIT_LIMIT 1000000

/* GP0 words per command, the command word included; a polyline up to its first segment (psx-spx
   "GPU Render Polygon/Line/Rectangle Commands", "GPU Memory Transfer Commands"). */
static inline int gp0_length(uint32_t word) {
  const uint32_t c = word >> 24, corners = (c & 0x08) ? 4 : 3;
  switch (c >> 5) {
    case 1: return (int)(1 + corners * ((c & 0x04) ? 2 : 1) + ((c & 0x10) ? corners - 1 : 0));
    case 2: return (c & 0x10) ? 4 : 3;
    case 3: return 2 + ((c & 0x04) ? 1 : 0) + (((c >> 3) & 3) == 0 ? 1 : 0);
    case 4: return 4;
    case 5:
    case 6: return 3;
    default: return c == 0x02 ? 3 : 1;
  }
}

/* The words the command under way still takes, and whether it is a polyline taking vertices
   until its 5xxx5xxx terminator: GPUSTAT.26 reads 0 until then (psx-spx "Ready Bits": the GPU
   wants more parameters), so gp0() waits for it only before a command word. */
static int gp0_left __attribute__((unused));
static int gp0_polyline __attribute__((unused));

static inline void gp0(uint32_t w) {
  if (gp0_left > 0) {
    --gp0_left;
  } else if (gp0_polyline) {
    if ((w & 0xF000F000u) == 0x50005000u) gp0_polyline = 0;
  } else {
    int i = 0;
    while (!(GPU_STAT & (1u << 26)) && ++i < GPU_WAIT_LIMIT) {
    }
    if (i == GPU_WAIT_LIMIT) TEST_TIMEOUT("GPUSTAT.26 (ready for a command)");
    gp0_left = gp0_length(w) - 1;
    gp0_polyline = (w >> 29) == 2 && (w & 0x08000000u);
  }
  GPU_GP0 = w;
}

/* 320x240 NTSC display of VRAM (0,0), drawing area = whole VRAM, offset 0, display on. */
static inline void gpu_init(void) {
  GPU_GP1 = 0x00000000;
  GPU_GP1 = 0x08000001;
  GPU_GP1 = 0x05000000;
  GPU_GP1 = 0x06C60260;
  GPU_GP1 = 0x07040010;
  gp0(0xE3000000);
  gp0(0xE4000000 | (511u << 10) | 1023u);
  gp0(0xE5000000);
  gp0(0x02000000);
  gp0(0);
  gp0(XY(1023, 511));
  GPU_GP1 = 0x03000000;
}

static inline void gpu_write_pixels(uint32_t x, uint32_t y, uint32_t w, uint32_t h, const uint16_t *p) {
  uint32_t n = w * h, i;
  gp0(0xA0000000);
  gp0(XY(x, y));
  gp0(XY(w, h));
  for (i = 0; i < n; i += 2) GPU_GP0 = p[i] | (i + 1 < n ? (uint32_t)p[i + 1] << 16 : 0);
}

static inline void gpu_poke(uint32_t x, uint32_t y, uint16_t v) { gpu_write_pixels(x, y, 1, 1, &v); }

static inline void gpu_read_pixels(uint32_t x, uint32_t y, uint32_t w, uint32_t h, uint16_t *out) {
  uint32_t n = w * h, i;
  gp0(0xC0000000);
  gp0(XY(x, y));
  gp0(XY(w, h));
  int spins = 0;
  while (!(GPU_STAT & (1u << 27)) && ++spins < GPU_WAIT_LIMIT) {
  }
  if (spins == GPU_WAIT_LIMIT) TEST_TIMEOUT("GPUSTAT.27 (VRAM data ready to send)");
  for (i = 0; i < n; i += 2) {
    uint32_t word = GPU_READ;
    out[i] = (uint16_t)word;
    if (i + 1 < n) out[i + 1] = (uint16_t)(word >> 16);
  }
}

static inline uint16_t gpu_peek(uint32_t x, uint32_t y) {
  uint16_t v;
  gpu_read_pixels(x, y, 1, 1, &v);
  return v;
}

#endif
