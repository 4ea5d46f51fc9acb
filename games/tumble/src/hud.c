/* Font texture upload, text drawing and the in-game HUD (see hud.h). */
#include "hud.h"

extern const uint16_t tumble_font_texture[32 * 64];

#define TEXT_NEUTRAL 0x808080 /* texture blending colour that keeps texels as they are */

void hud_init(void) {
  /* 4bpp palette: 0 transparent (0000h is never drawn), 1 white glyph, 2 opaque black shadow
     (8000h: black with the mask bit, which the GPU draws). */
  uint16_t clut[16] = {0x0000, 0x7FFF, 0x8000};
  gpu_upload(FONT_VRAM_X, 0, 32, 64, tumble_font_texture);
  gpu_upload(FONT_VRAM_X, FONT_CLUT_Y, 16, 1, clut);
}

static void font_page(Gpu *gpu) {
  uint32_t *p = gpu_prim(gpu, 0, 1);
  if (p) p[0] = 0xE1000000 | 0x200 | gpu_texpage(FONT_VRAM_X, 0, 0);
}

static int glyph(char c) {
  if (c >= 'a' && c <= 'z') c = (char)(c - 32);
  return c < 32 || c > 95 ? 0 : c - 32;
}

void hud_text(Gpu *gpu, int x, int y, const char *s, uint32_t colour) {
  uint32_t clut = gpu_clut(FONT_VRAM_X, FONT_CLUT_Y);
  for (; *s; ++s, x += 8) {
    int g = glyph(*s);
    if (!g) continue;
    uint32_t *p = gpu_prim(gpu, 0, 3);
    if (!p) return;
    p[0] = 0x74000000 | colour;  /* GP0(74h) 8x8 textured sprite, texture blended */
    p[1] = gpu_xy(x, y);
    p[2] = clut << 16 | (uint32_t)(g / 16 * 16) << 8 | (uint32_t)(g % 16 * 8);
  }
  /* Linked after the sprites, so drawn before them: sprites take their page from GP0(E1h). */
  font_page(gpu);
}

void hud_text_big(Gpu *gpu, int x, int y, const char *s, int scale, uint32_t colour) {
  uint32_t clut = gpu_clut(FONT_VRAM_X, FONT_CLUT_Y), page = gpu_texpage(FONT_VRAM_X, 0, 0);
  int size = 8 * scale;
  for (; *s; ++s, x += size) {
    int g = glyph(*s);
    if (!g) continue;
    uint32_t u = (uint32_t)(g % 16 * 8), v = (uint32_t)(g / 16 * 16);
    uint32_t *p = gpu_prim(gpu, 0, 9);
    if (!p) return;
    p[0] = 0x2C000000 | colour;  /* GP0(2Ch) textured quad, texture blended */
    p[1] = gpu_xy(x, y);
    p[2] = clut << 16 | v << 8 | u;
    p[3] = gpu_xy(x + size, y);
    p[4] = page << 16 | v << 8 | (u + 8);
    p[5] = gpu_xy(x, y + size);
    p[6] = (v + 8) << 8 | u;
    p[7] = gpu_xy(x + size, y + size);
    p[8] = (v + 8) << 8 | (u + 8);
  }
}

int hud_centre(const char *s, int scale) {
  int n = 0;
  while (s[n]) ++n;
  return (SCREEN_W - n * 8 * scale) / 2;
}

char *hud_number(char *out, uint32_t value, int digits) {
  char tmp[12];
  int n = 0;
  do {
    tmp[n++] = (char)('0' + value % 10);
    value /= 10;
  } while (value || n < digits);
  for (int i = 0; i < n; ++i) out[i] = tmp[n - 1 - i];
  out[n] = 0;
  return out;
}

char *hud_cat(char *a, const char *b) {
  char *end = a;
  while (*end) ++end;
  while ((*end++ = *b++)) {
  }
  return a;
}

void hud_draw(Gpu *gpu, const Game *g) {
  const TumbleContract *p = &g->pub;
  char line[40], num[12];
  line[0] = 0;
  hud_text(gpu, 12, 10, hud_cat(hud_cat(line, "SCORE "), hud_number(num, p->score, 5)), TEXT_NEUTRAL);
  uint32_t seconds = (p->clock + 59) / 60;
  line[0] = 0;
  hud_text(gpu, 228, 10, hud_cat(hud_cat(line, "TIME "), hud_number(num, seconds, 3)),
           seconds <= 10 && (p->frame & 16) ? 0x4040C0 : TEXT_NEUTRAL);
  line[0] = 0;
  hud_cat(hud_cat(line, "KEYS "), hud_number(num, p->keys_held, 1));
  hud_text(gpu, 12, 222, hud_cat(hud_cat(line, "/"), hud_number(num, p->keys_needed, 1)),
           p->keys_held >= p->keys_needed ? 0x40C040 : TEXT_NEUTRAL);
  line[0] = 0;
  hud_text(gpu, 244, 222, hud_cat(hud_cat(line, "LEVEL "), hud_number(num, p->level, 2)), TEXT_NEUTRAL);
}
