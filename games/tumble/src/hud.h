/* Text on screen from the generated font texture (8x8 glyphs, ASCII 32..95): small text as 8x8
   textured sprites, large text as scaled textured quads, and the in-game HUD (score, clock,
   keys, level). Text goes into ordering-table slot 0, drawn after the scene. */
#ifndef TUMBLE_HUD_H
#define TUMBLE_HUD_H
#include <stdint.h>
#include "game.h"
#include "gpu.h"

/* Uploads the font texture and its palette to VRAM. */
void hud_init(void);
void hud_text(Gpu *gpu, int x, int y, const char *s, uint32_t colour);
void hud_text_big(Gpu *gpu, int x, int y, const char *s, int scale, uint32_t colour);
/* x that centres `s` at `scale` (1 for 8x8 text). */
int hud_centre(const char *s, int scale);
/* Writes `value` in decimal, at least `digits` wide with leading zeros, into `out`; returns out. */
char *hud_number(char *out, uint32_t value, int digits);
/* Concatenates `b` onto `a` (a must have room). */
char *hud_cat(char *a, const char *b);
void hud_draw(Gpu *gpu, const Game *g);

#endif
