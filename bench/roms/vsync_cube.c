/* VSync-bound workload for the benchmarks, shaped like the SDK examples emulators are compared on
   (a spinning cube that waits for VSync): each frame the GTE transforms a cube (RTPT, RTPS,
   NCLIP, AVSZ4), its visible faces go into an ordering table cleared by DMA channel 6 (OTC), the
   table goes to the GPU by DMA channel 2 in linked-list mode, and the program waits for the GPU
   and then for VBlank with timer 1 counting HBlanks, as Sony's libetc VSync() does (it reads
   timer 1 for the lines since the last call). Double-buffered: draws one half of VRAM while the
   other is shown. Register addresses and bits from psx-spx ("DMA Channels", "Timers",
   "Interrupt Control", "GPU Display Control Commands"). */
#include <stdint.h>

#include "bench_video.h"
#include "gte.h"

#define REG(a) (*(volatile uint32_t *)(a))
#define I_STAT REG(0x1F801070)
#define DPCR REG(0x1F8010F0)
#define D2_MADR REG(0x1F8010A0)
#define D2_BCR REG(0x1F8010A4)
#define D2_CHCR REG(0x1F8010A8)
#define D6_MADR REG(0x1F8010E0)
#define D6_BCR REG(0x1F8010E4)
#define D6_CHCR REG(0x1F8010E8)
#define T1_COUNT REG(0x1F801110)
#define T1_MODE REG(0x1F801114)

#define OT_LEN 64
#define CHCR_BUSY (1u << 24)
#define GPUSTAT_READY (1u << 26)

static uint32_t ot[OT_LEN];
static uint32_t packets[6 * 6]; /* six POLY_F4: a tag word, then command + colour and 4 vertices */
static volatile uint32_t lines_per_frame;

static const int16_t verts[8][3] = {{-100, -100, -100}, {100, -100, -100}, {-100, 100, -100}, {100, 100, -100},
                                    {100, -100, 100},   {-100, -100, 100}, {100, 100, 100},   {-100, 100, 100}};
static const uint8_t faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {5, 4, 0, 1}, {6, 7, 3, 2}, {0, 2, 5, 7}, {3, 1, 6, 4}};
static const uint32_t colours[6] = {0xC04040, 0x40C040, 0x4040C0, 0xC0C040, 0x40C0C0, 0xC040C0};

/* DMA6 (OTC) writes OT_LEN words downwards from the last: each points at the one below, the
   first holds the end marker FFFFFFh. */
static void clear_ot(void) {
  D6_MADR = (uint32_t)&ot[OT_LEN - 1];
  D6_BCR = OT_LEN;
  D6_CHCR = 0x11000002;
  while (D6_CHCR & CHCR_BUSY) {
  }
}

static void add_prim(uint32_t z, uint32_t *prim, uint32_t words) {
  prim[0] = (words << 24) | (ot[z] & 0xFFFFFF);
  ot[z] = (ot[z] & 0xFF000000) | ((uint32_t)prim & 0xFFFFFF);
}

/* Rotation about Y by (c, s), then about X by (c, s): RT = Rx * Ry (4.12). */
static void set_rotation(int32_t c, int32_t s) {
  int32_t r11 = c, r12 = 0, r13 = s;
  int32_t r21 = (s * s) >> 12, r22 = c, r23 = -((s * c) >> 12);
  int32_t r31 = -((c * s) >> 12), r32 = s, r33 = (c * c) >> 12;
  gte_ctc2((uint32_t)(r11 & 0xFFFF) | (uint32_t)r12 << 16, 0);
  gte_ctc2((uint32_t)(r13 & 0xFFFF) | (uint32_t)r21 << 16, 1);
  gte_ctc2((uint32_t)(r22 & 0xFFFF) | (uint32_t)r23 << 16, 2);
  gte_ctc2((uint32_t)(r31 & 0xFFFF) | (uint32_t)r32 << 16, 3);
  gte_ctc2((uint32_t)(r33 & 0xFFFF), 4);
}

static void draw_cube(void) {
  uint32_t *prim = packets;
  for (int f = 0; f < 6; ++f) {
    const int16_t *a = verts[faces[f][0]], *b = verts[faces[f][1]], *c = verts[faces[f][2]], *d = verts[faces[f][3]];
    gte_load_v0(a[0], a[1], a[2]);
    gte_load_v1(b[0], b[1], b[2]);
    gte_load_v2(c[0], c[1], c[2]);
    gte_cmd(GTE_RTPT);
    gte_cmd(GTE_NCLIP);
    if ((int32_t)gte_mfc2(24) <= 0) continue; /* facing away */
    const uint32_t xy0 = gte_mfc2(12), xy1 = gte_mfc2(13), xy2 = gte_mfc2(14);
    gte_load_v0(d[0], d[1], d[2]);
    gte_cmd(GTE_RTPS);
    gte_cmd(GTE_AVSZ4);
    uint32_t z = gte_mfc2(7) >> 2;
    if (z >= OT_LEN) z = OT_LEN - 1;
    prim[1] = 0x28000000 | colours[f];
    prim[2] = xy0;
    prim[3] = xy1;
    prim[4] = xy2;
    prim[5] = gte_mfc2(14);
    add_prim(z, prim, 5);
    prim += 6;
  }
}

/* Waits for the GPU, then for the next VBlank (I_STAT bit 0), and notes the HBlanks timer 1
   counted since the last one (263 a progressive NTSC frame). */
static void vsync(void) {
  static uint32_t last;
  while (D2_CHCR & CHCR_BUSY) {
  }
  while (!(GP1 & GPUSTAT_READY)) {
  }
  while (!(I_STAT & 1)) {
  }
  I_STAT = ~1u;
  const uint32_t now = T1_COUNT & 0xFFFF;
  lines_per_frame = (now - last) & 0xFFFF;
  last = now;
}

int main(void) {
  enable_gte();
  display_320x240();
  GP1 = 0x04000002;  /* DMA direction CPU to GP0 */
  DPCR |= 0x08000800; /* enable DMA channels 2 and 6 */
  T1_MODE = 0x0100;  /* timer 1 counts HBlanks */
  gte_ctc2(0, 5);
  gte_ctc2(0, 6);
  gte_ctc2(500, 7);           /* translation: 500 in front of the camera */
  gte_ctc2(160 << 16, 24);    /* screen centre */
  gte_ctc2(120 << 16, 25);
  gte_ctc2(160, 26);          /* projection distance */
  gte_ctc2(0x100, 30);        /* ZSF4 = 4096/16 */
  int32_t c = 4096, s = 0;
  for (uint32_t frame = 0;; ++frame) {
    const uint32_t half = frame & 1, x0 = half * 320;
    set_rotation(c, s);
    int32_t nc = c - (s >> 5), ns = s + (c >> 5);
    c = nc;
    s = ns;
    if (c * c + s * s > 4096 * 4096 + 65536) { c -= c >> 8; s -= s >> 8; }
    clear_ot();
    draw_cube();
    GP0 = 0xE3000000 | x0;                        /* drawing area */
    GP0 = 0xE4000000 | (239u << 10) | (x0 + 319);
    GP0 = 0xE5000000 | x0;                        /* drawing offset */
    GP0 = 0x02000000 | 0x7F003F;                  /* clear the half drawn into */
    GP0 = x0;
    GP0 = (240u << 16) | 320u;
    D2_MADR = (uint32_t)&ot[OT_LEN - 1];
    D2_BCR = 0;
    D2_CHCR = 0x01000401; /* linked list, from RAM */
    vsync();
    GP1 = 0x05000000 | x0; /* show what was drawn */
  }
  return 0;
}
