/* Drawing a level in play: sky, tiles (textured, Gouraud-shaded by distance), spikes (GTE-culled
   pyramids), items, the exit and the ball, from the camera that follows the ball. */
#ifndef TUMBLE_SCENE_H
#define TUMBLE_SCENE_H
#include "game.h"
#include "gpu.h"

void scene_sky(Gpu *gpu);
void scene_draw(Gpu *gpu, const Game *g);
/* Stores the camera eye position of this frame in the RAM contract (camera_x/y/z). */
void scene_update_camera(Game *g);

#endif
