/* A picture known by construction, for psxrl compat's tests (tests/unit/cli_compat_test.cpp):
   a 320x240 display (gpu_init) whose left half is filled with one colour and right half with
   another by GP0(02h) (psx-spx "GPU Render Misc Commands"), so its final frame has exactly two
   distinct colours. It uses no BIOS call, so the HLE kernel and any boot ROM show the same
   picture; and it never exits, so a compat run lasts all its frames. */
#include "gpu_rom.h"

static void fill(uint32_t x, uint32_t y, uint32_t w, uint32_t h, uint32_t bgr) {
  gp0(0x02000000 | bgr);
  gp0(XY(x, y));
  gp0(XY(w, h));
}

int main(void) {
  gpu_init();
  fill(0, 0, 160, 240, 0xC06020);   /* B G R: a blue */
  fill(160, 0, 160, 240, 0x2080F0); /* an orange */
  for (;;) {
  }
}
