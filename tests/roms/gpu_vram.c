/* VRAM commands and status through the ports: fill rounding, CPU->VRAM with odd sizes and wrap,
   VRAM->CPU, VRAM->VRAM copy, mask bit handling, GPUSTAT bits, GP1(10h) info and GP0(1Fh).
   Expected values from psx-spx. */
#include "gpu_rom.h"

#define I_STAT (*(volatile uint32_t *)0xBF801070)

static void fill(void) {
  /* x 0x13 -> 0x10, width 0x11 -> 0x20: columns 16..47 of rows 100..101. */
  gp0(0x020000F8);
  gp0(XY(0x13, 100));
  gp0(XY(0x11, 2));
  CHECK_EQ("fill left of x", gpu_peek(15, 100), 0);
  CHECK_EQ("fill first", gpu_peek(16, 100), RGB15(31, 0, 0));
  CHECK_EQ("fill last", gpu_peek(47, 101), RGB15(31, 0, 0));
  CHECK_EQ("fill past width", gpu_peek(48, 100), 0);
  CHECK_EQ("fill past height", gpu_peek(16, 102), 0);
}

static void transfers(void) {
  uint16_t out[4];
  /* 3x1 at x = 1022 wraps to x = 0; the fourth halfword of the last word is dropped. */
  gp0(0xA0000000);
  gp0(XY(1022, 110));
  gp0(XY(3, 1));
  GPU_GP0 = 0x22221111;
  GPU_GP0 = 0x44443333;
  CHECK_EQ("wrap 1022", gpu_peek(1022, 110), 0x1111);
  CHECK_EQ("wrap 1023", gpu_peek(1023, 110), 0x2222);
  CHECK_EQ("wrap 0", gpu_peek(0, 110), 0x3333);
  CHECK_EQ("dropped", gpu_peek(1, 110), 0);
  /* Read a 2x2 block back across the wrap. */
  gpu_read_pixels(1023, 110, 2, 2, out);
  CHECK_EQ("read 0", out[0], 0x2222);
  CHECK_EQ("read 1", out[1], 0x3333);
  CHECK_EQ("read 2", out[2], 0);
  CHECK_EQ("ready flag cleared", (GPU_STAT >> 27) & 1, 0);
  /* VRAM->VRAM copy of 3 pixels from (1022,110) to (60,100). */
  gp0(0x80000000);
  gp0(XY(1022, 110));
  gp0(XY(60, 100));
  gp0(XY(3, 1));
  CHECK_EQ("copy 0", gpu_peek(60, 100), 0x1111);
  CHECK_EQ("copy 2", gpu_peek(62, 100), 0x3333);
}

static void mask(void) {
  gpu_poke(70, 100, 0x8001);
  gp0(0xE6000003); /* set and check */
  gp0(0x680000F8);
  gp0(XY(70, 100));
  gp0(0x680000F8);
  gp0(XY(71, 100));
  CHECK_EQ("mask protects", gpu_peek(70, 100), 0x8001);
  CHECK_EQ("mask set", gpu_peek(71, 100), 0x801F);
  CHECK_EQ("GPUSTAT mask bits", (GPU_STAT >> 11) & 3, 3);
  gp0(0xE6000000);
}

static void status_and_info(void) {
  gp0(0xE2012345);
  gp0(0xE5123456);
  GPU_GP1 = 0x10000002;
  CHECK_EQ("info texture window", GPU_READ, 0x12345);
  GPU_GP1 = 0x10000005;
  CHECK_EQ("info draw offset", GPU_READ, 0x123456);
  GPU_GP1 = 0x10000007;
  CHECK_EQ("info GPU type", GPU_READ, 2);
  gp0(0xE2000000);
  gp0(0xE5000000);
  /* 320 wide (bits 17-18 = 1), NTSC, 15-bit, display on (bit 23 = 0). */
  CHECK_EQ("GPUSTAT display mode", (GPU_STAT >> 16) & 0xFF, 2);
  CHECK_EQ("GPUSTAT ready", (GPU_STAT >> 26) & 5, 5);
  GPU_GP1 = 0x04000002;
  CHECK_EQ("GPUSTAT DMA direction", (GPU_STAT >> 29) & 3, 2);
  CHECK_EQ("GPUSTAT DMA request = bit 28", (GPU_STAT >> 25) & 1, 1);
  GPU_GP1 = 0x04000000;
  gp0(0x1F000000);
  CHECK_EQ("IRQ1 flag", (GPU_STAT >> 24) & 1, 1);
  CHECK_EQ("IRQ1 line", (I_STAT >> 1) & 1, 1);
  GPU_GP1 = 0x02000000;
  I_STAT = ~2u;
  CHECK_EQ("IRQ1 acknowledged", (GPU_STAT >> 24) & 1, 0);
}

static void vblank(void) {
  /* The VBlank interrupt (I_STAT bit 0) comes within a frame (~566000 cycles). */
  int spins = 0;
  I_STAT = ~1u;
  while (!(I_STAT & 1) && spins < 1000000) ++spins;
  CHECK_EQ("vblank irq", I_STAT & 1, 1);
}

int main(void) {
  gpu_init();
  fill();
  transfers();
  mask();
  status_and_info();
  vblank();
  return test_done("gpu_vram");
}
