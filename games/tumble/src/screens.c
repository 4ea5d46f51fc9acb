/* Per-state screen composition (see screens.h). */
#include "screens.h"
#include "hud.h"
#include "scene.h"

#define WHITE 0x808080
#define GOLD 0x2090C0 /* blended: red 1.5, green 1.1, blue 0.25 of the white glyph */
#define RED 0x3030C0

static void centred(Gpu *gpu, int y, const char *s, int scale, uint32_t colour) {
  if (scale == 1) hud_text(gpu, hud_centre(s, 1), y, s, colour);
  else hud_text_big(gpu, hud_centre(s, scale), y, s, scale, colour);
}

static void title(Gpu *gpu, const Game *g) {
  scene_sky(gpu);
  centred(gpu, 60, "TUMBLE", 5, GOLD);
  centred(gpu, 120, "ROLL  JUMP  COLLECT  ESCAPE", 1, WHITE);
  if (g->pub.frame & 32) centred(gpu, 170, "PRESS START", 1, WHITE);
  centred(gpu, 214, "PSXRL", 1, 0x606060);
}

static void level_select(Gpu *gpu, const Game *g) {
  const TumbleContract *p = &g->pub;
  const LevelDef *def = &tumble_levels[p->menu_level - 1];
  char line[40], num[12];
  scene_sky(gpu);
  centred(gpu, 40, "SELECT LEVEL", 2, GOLD);
  line[0] = 0;
  centred(gpu, 90, hud_cat(hud_cat(hud_cat(line, "< "), hud_number(num, p->menu_level, 2)), " >"), 3, WHITE);
  centred(gpu, 130, def->name, 1, WHITE);
  line[0] = 0;
  centred(gpu, 146, hud_cat(hud_cat(line, "TIME "), hud_number(num, def->time_seconds, 1)), 1, WHITE);
  centred(gpu, 196, "LEFT RIGHT CHOOSE   X START", 1, 0x606060);
}

static void in_play(Gpu *gpu, const Game *g) {
  const TumbleContract *p = &g->pub;
  scene_draw(gpu, g);
  hud_draw(gpu, g);
  char line[40], num[12];
  switch (p->state) {
    case STATE_SPIKED: centred(gpu, 100, "SPIKED!", 3, RED); break;
    case STATE_FALLEN: centred(gpu, 100, "YOU FELL!", 3, RED); break;
    case STATE_TIME_UP: centred(gpu, 100, "TIME UP!", 3, RED); break;
    case STATE_SUCCESS:
      centred(gpu, 80, "LEVEL COMPLETE", 2, GOLD);
      line[0] = 0;
      centred(gpu, 120, hud_cat(hud_cat(line, "SCORE "), hud_number(num, p->score, 1)), 2, WHITE);
      break;
    default:
      if (p->state_timer < 90) centred(gpu, 60, tumble_levels[p->level - 1].name, 2, WHITE);
      break;
  }
}

static void game_over(Gpu *gpu, const Game *g) {
  char line[40], num[12];
  scene_sky(gpu);
  centred(gpu, 80, "GAME OVER", 4, RED);
  line[0] = 0;
  centred(gpu, 140, hud_cat(hud_cat(line, "LEVELS COMPLETED "), hud_number(num, g->pub.levels_completed, 1)), 1, WHITE);
  if (g->pub.frame & 32) centred(gpu, 180, "PRESS START", 1, WHITE);
}

void screens_draw(Gpu *gpu, const Game *g) {
  switch (g->pub.state) {
    case STATE_TITLE: title(gpu, g); break;
    case STATE_LEVEL_SELECT: level_select(gpu, g); break;
    case STATE_GAME_OVER: game_over(gpu, g); break;
    case STATE_PLAYING:
    case STATE_SPIKED:
    case STATE_FALLEN:
    case STATE_TIME_UP:
    case STATE_SUCCESS: in_play(gpu, g); break;
    default: scene_sky(gpu); break;
  }
}
