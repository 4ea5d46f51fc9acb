/* GTE- and GPU-bound workload for the benchmarks: a spinning wall of 384 triangles, each frame
   transformed three vertices at a time by the GTE (RTPT, NCLIP, AVSZ3) and drawn as Gouraud-shaded
   triangles written straight to GP0, with no waiting for VBlank: work as a 3D game does it, with
   no idle time. Uses Tumble's GTE access macros (games/tumble/src/gte.h). */
#include <stdint.h>

#include "bench_video.h"
#include "gte.h"

static void gpu_setup(void) {
  display_320x240();
  GP0 = 0xE1000200;                 /* dither on */
  GP0 = 0xE3000000;                 /* drawing area 0,0 .. */
  GP0 = 0xE4000000 | (239u << 10) | 319u;
  GP0 = 0xE5000000;                 /* drawing offset 0,0 */
}

/* Rotation about Y by the angle whose cosine and sine (4.12) are c and s. */
static void set_rotation(int32_t c, int32_t s) {
  gte_ctc2((uint32_t)(c & 0xFFFF), 0);               /* RT11=c, RT12=0 */
  gte_ctc2((uint32_t)(s & 0xFFFF) << 16, 1);         /* RT13=s, RT21=0 */
  gte_ctc2(0x1000, 2);                               /* RT22=1, RT23=0 */
  gte_ctc2((uint32_t)(-s & 0xFFFF), 3);              /* RT31=-s, RT32=0 */
  gte_ctc2((uint32_t)(c & 0xFFFF), 4);               /* RT33=c */
}

int main(void) {
  enable_gte();
  gpu_setup();
  gte_ctc2(0, 5);
  gte_ctc2(0, 6);
  gte_ctc2(1200, 7);                 /* translation: 1200 in front of the camera */
  gte_ctc2(160 << 16, 24);           /* screen centre */
  gte_ctc2(120 << 16, 25);
  gte_ctc2(300, 26);                 /* projection distance */
  gte_ctc2(0x155, 29);               /* ZSF3 = 4096/12 */
  /* A cheap cosine/sine walk: (c, s) rotated by a small angle each frame, renormalised. */
  int32_t c = 4096, s = 0;
  for (uint32_t frame = 0;; ++frame) {
    set_rotation(c, s);
    int32_t nc = c - (s >> 6), ns = s + (c >> 6);
    c = nc;
    s = ns;
    if (c * c + s * s > 4096 * 4096 + 65536) { c -= c >> 8; s -= s >> 8; }
    GP0 = 0x02000000 | 0x101010;     /* clear the frame */
    GP0 = 0;
    GP0 = (240u << 16) | 320u;
    for (int32_t gy = -8; gy < 8; ++gy) {
      for (int32_t gx = -12; gx < 12; ++gx) {
        int32_t x = gx * 40, y = gy * 40, z = (gx * gy) & 63;
        gte_load_v0(x, y, z);
        gte_load_v1(x + 40, y, z);
        gte_load_v2(x, y + 40, z);
        gte_cmd(GTE_RTPT);
        gte_cmd(GTE_NCLIP);
        gte_cmd(GTE_AVSZ3);
        uint32_t xy0 = gte_mfc2(12), xy1 = gte_mfc2(13), xy2 = gte_mfc2(14);
        uint32_t shade = (uint32_t)(gx + 12) * 8 + frame;
        GP0 = 0x30000000 | (shade & 0xFF);
        GP0 = xy0;
        GP0 = 0x00FF00 | ((shade * 3) & 0xFF) << 16;
        GP0 = xy1;
        GP0 = 0x0000FF | ((shade * 5) & 0xFF) << 8;
        GP0 = xy2;
      }
    }
  }
  return 0;
}
