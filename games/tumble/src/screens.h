/* What the screen shows in each game state: title, level select, the level in play with its HUD,
   the lost messages (spiked, fallen, time up), level complete and game over. */
#ifndef TUMBLE_SCREENS_H
#define TUMBLE_SCREENS_H
#include "game.h"
#include "gpu.h"

void screens_draw(Gpu *gpu, const Game *g);

#endif
