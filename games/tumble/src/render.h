/* 3D view for Tumble on the GTE: world units (a tile is 256 units, y up, x east, z south), a
   camera behind and above the ball looking along the view yaw and tilted down, fixed-point
   sine/cosine, and projection of vertices to screen coordinates and ordering-table depth. */
#ifndef TUMBLE_RENDER_H
#define TUMBLE_RENDER_H
#include <stdint.h>

#define TILE 256
#define PROJ_H 220
#define NEAR_Z 96

/* sin/cos of `angle` (4096 = full turn), 4.12 fixed point. */
int32_t fx_sin(uint32_t angle);
int32_t fx_cos(uint32_t angle);

/* Sets up the GTE: camera at (x, y, z) looking along `yaw`, pitched down. */
void render_camera(int32_t x, int32_t y, int32_t z, uint32_t yaw);

typedef struct Vert { int32_t x, y, z; } Vert;
typedef struct Screen { int16_t x, y; int32_t z; } Screen;

/* Projects three vertices (RTPT); returns 0 when one is too near or far off-screen. */
int render_project3(const Vert v[3], Screen out[3]);
/* Projects one vertex (RTPS); same result rule. */
int render_project1(const Vert *v, Screen *out);
/* Ordering-table slot for a depth (larger is farther, drawn first). */
int render_ot_z(int32_t sz);
/* Ordering-table slot from the GTE's average of the last 3 (AVSZ3) or 4 (AVSZ4) depths. */
int render_avsz3(void);
int render_avsz4(void);
/* Winding of the last projected three vertices (NCLIP): > 0 when clockwise on screen. */
int32_t render_nclip(void);

#endif
