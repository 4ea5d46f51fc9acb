/* Level rendering (see scene.h). World: tile (x, y) covers x*TILE..(x+1)*TILE east and
   y*TILE..(y+1)*TILE south, its top at height 0. */
#include "scene.h"
#include "moves.h"
#include "render.h"

#define BALL_R 80
#define CAM_BACK 700
#define CAM_UP 420

static uint32_t shade(int r, int g, int b, int32_t z) {
  /* Fade toward the sky with distance: full colour up to z 600, 40% at z 3000 and beyond. */
  int32_t f = z <= 600 ? 256 : z >= 3000 ? 102 : 256 - (z - 600) * 154 / 2400;
  return gpu_rgb(r * f >> 8, g * f >> 8, b * f >> 8);
}

void scene_sky(Gpu *gpu) {
  uint32_t *p = gpu_prim(gpu, OT_LEN - 1, 8);
  if (!p) return;
  p[0] = 0x38000000 | gpu_rgb(20, 30, 90);  /* GP0(38h) Gouraud quad, opaque */
  p[1] = gpu_xy(0, 0);
  p[2] = gpu_rgb(20, 30, 90);
  p[3] = gpu_xy(SCREEN_W, 0);
  p[4] = gpu_rgb(120, 150, 210);
  p[5] = gpu_xy(0, SCREEN_H);
  p[6] = gpu_rgb(120, 150, 210);
  p[7] = gpu_xy(SCREEN_W, SCREEN_H);
}

static void tile_colour(const Game *g, int x, int y, int *r, int *gr, int *b) {
  *r = *gr = *b = 128;
  switch (g->tile[y][x]) {
    case TILE_EXIT:
      if (g->pub.keys_held >= g->pub.keys_needed) *r = 40, *gr = 220, *b = 60;
      else *r = 170, *gr = 50, *b = 50;
      break;
    case TILE_CRUMBLE:
      *r = 170, *gr = 120, *b = 70;
      if (g->crumble_timer[y][x] && (g->crumble_timer[y][x] & 4)) *r = 220, *gr = 60, *b = 40;
      break;
    case TILE_SPIKES: *r = 100, *gr = 100, *b = 110; break;
    default: break;
  }
}

static void draw_tile(Gpu *gpu, const Game *g, int x, int y) {
  int32_t x0 = x * TILE, x1 = x0 + TILE, z0 = y * TILE, z1 = z0 + TILE;
  Vert v[3] = {{x0, 0, z0}, {x1, 0, z0}, {x0, 0, z1}};
  Vert v3 = {x1, 0, z1};
  Screen s[4];
  if (!render_project3(v, s) || !render_project1(&v3, &s[3])) return;
  int ot = render_avsz4();
  int r, gr, b;
  tile_colour(g, x, y, &r, &gr, &b);
  uint32_t *p = gpu_prim(gpu, ot, 12);
  if (!p) return;
  uint32_t page = gpu_texpage(TILE_VRAM_X, 0, 2);
  p[0] = 0x3C000000 | shade(r, gr, b, s[0].z); /* GP0(3Ch) textured Gouraud quad */
  p[1] = gpu_xy(s[0].x, s[0].y);
  p[2] = 0x0000;
  p[3] = shade(r, gr, b, s[1].z);
  p[4] = gpu_xy(s[1].x, s[1].y);
  p[5] = page << 16 | 31;
  p[6] = shade(r, gr, b, s[2].z);
  p[7] = gpu_xy(s[2].x, s[2].y);
  p[8] = 31 << 8;
  p[9] = shade(r, gr, b, s[3].z);
  p[10] = gpu_xy(s[3].x, s[3].y);
  p[11] = 31 << 8 | 31;
}

/* One face of a spike pyramid; drawn only when the GTE finds it facing the camera. */
static void spike_face(Gpu *gpu, Vert a, Vert b, Vert apex) {
  Vert v[3] = {a, b, apex};
  Screen s[3];
  if (!render_project3(v, s) || render_nclip() <= 0) return;
  int ot = render_avsz3() - 1;
  uint32_t *p = gpu_prim(gpu, ot, 6);
  if (!p) return;
  p[0] = 0x30000000 | shade(90, 90, 100, s[0].z); /* GP0(30h) Gouraud triangle */
  p[1] = gpu_xy(s[0].x, s[0].y);
  p[2] = shade(90, 90, 100, s[1].z);
  p[3] = gpu_xy(s[1].x, s[1].y);
  p[4] = shade(235, 235, 245, s[2].z);
  p[5] = gpu_xy(s[2].x, s[2].y);
}

static void draw_spikes(Gpu *gpu, int x, int y) {
  int32_t cx = x * TILE + TILE / 2, cz = y * TILE + TILE / 2;
  for (int i = 0; i < 4; ++i) {
    int32_t px = cx + (i & 1 ? 56 : -56), pz = cz + (i & 2 ? 56 : -56);
    Vert c0 = {px - 48, 0, pz - 48}, c1 = {px + 48, 0, pz - 48};
    Vert c2 = {px - 48, 0, pz + 48}, c3 = {px + 48, 0, pz + 48};
    Vert apex = {px, 150, pz};
    spike_face(gpu, c0, c1, apex);
    spike_face(gpu, c1, c3, apex);
    spike_face(gpu, c3, c2, apex);
    spike_face(gpu, c2, c0, apex);
  }
}

/* A Gouraud diamond standing at a world point, sized by distance. */
static void billboard_diamond(Gpu *gpu, Vert at, int half_w, int half_h, uint32_t top, uint32_t bottom, int bias) {
  Screen s;
  if (!render_project1(&at, &s)) return;
  int w = half_w * PROJ_H / s.z, h = half_h * PROJ_H / s.z;
  uint32_t *p = gpu_prim(gpu, render_ot_z(s.z) - bias, 8);
  if (!p) return;
  p[0] = 0x38000000 | top;
  p[1] = gpu_xy(s.x, s.y - h);
  p[2] = top;
  p[3] = gpu_xy(s.x - w, s.y);
  p[4] = bottom;
  p[5] = gpu_xy(s.x + w, s.y);
  p[6] = bottom;
  p[7] = gpu_xy(s.x, s.y + h);
}

static void draw_item(Gpu *gpu, const Game *g, int x, int y) {
  Vert at = {x * TILE + TILE / 2, 90, y * TILE + TILE / 2};
  int spin = fx_cos(g->pub.frame * 48) * 40 >> 12;
  spin = spin < 0 ? -spin : spin;
  switch (g->item[y][x]) {
    case ITEM_COIN: billboard_diamond(gpu, at, spin + 6, 44, gpu_rgb(255, 230, 80), gpu_rgb(170, 110, 0), 1); break;
    case ITEM_FRUIT: billboard_diamond(gpu, at, 44, 44, gpu_rgb(255, 90, 90), gpu_rgb(150, 0, 40), 1); break;
    case ITEM_KEY: billboard_diamond(gpu, at, spin / 2 + 10, 60, gpu_rgb(140, 255, 255), gpu_rgb(0, 120, 200), 1); break;
    default: break;
  }
}

static void ball_position(const Game *g, Vert *ball) {
  const TumbleContract *p = &g->pub;
  int32_t x = (int32_t)p->ball_x * TILE, z = (int32_t)p->ball_y * TILE, h = 0;
  if (p->state == STATE_PLAYING && p->move != MOVE_NONE) {
    int32_t t = (int32_t)move_travel_progress(p->move, p->move_frame);
    x = g->from_x * TILE + (g->to_x - g->from_x) * TILE * t / 256;
    z = g->from_y * TILE + (g->to_y - g->from_y) * TILE * t / 256;
    h = (int32_t)move_jump_height(p->move, p->move_frame) * TILE / 256;
  }
  if (p->state == STATE_FALLEN) h = -(int32_t)(p->state_timer * p->state_timer) / 2;
  ball->x = x + TILE / 2;
  ball->y = h + BALL_R;
  ball->z = z + TILE / 2;
}

static void draw_ball(Gpu *gpu, const Game *g, const Vert *ball) {
  Screen c;
  if (!render_project1(ball, &c)) return;
  int r = BALL_R * PROJ_H / c.z;
  int ot = render_ot_z(c.z) - 2;
  int spiked = g->pub.state == STATE_SPIKED;
  uint32_t rim = spiked ? gpu_rgb(90, 0, 0) : gpu_rgb(150, 30, 20);
  uint32_t mid = spiked ? gpu_rgb(200, 40, 40) : gpu_rgb(255, 210, 170);
  int hx = c.x - r / 3, hy = c.y - r / 3;
  for (int i = 0; i < 12; ++i) {
    uint32_t a0 = (uint32_t)i * 4096 / 12, a1 = (uint32_t)(i + 1) * 4096 / 12;
    uint32_t *p = gpu_prim(gpu, ot, 6);
    if (!p) return;
    p[0] = 0x30000000 | mid;
    p[1] = gpu_xy(hx, hy);
    p[2] = rim;
    p[3] = gpu_xy(c.x + (fx_cos(a0) * r >> 12), c.y + (fx_sin(a0) * r >> 12));
    p[4] = rim;
    p[5] = gpu_xy(c.x + (fx_cos(a1) * r >> 12), c.y + (fx_sin(a1) * r >> 12));
  }
}

/* The camera eye: behind the ball along the view yaw and above it, never below floor height. */
static void camera_eye(const Game *g, const Vert *ball, Vert *eye) {
  uint32_t yaw = g->pub.camera_angle;
  int32_t fy = ball->y < BALL_R ? BALL_R : ball->y;
  eye->x = ball->x - (fx_sin(yaw) * CAM_BACK >> 12);
  eye->y = fy + CAM_UP;
  eye->z = ball->z + (fx_cos(yaw) * CAM_BACK >> 12);
}

void scene_update_camera(Game *g) {
  Vert ball, eye;
  ball_position(g, &ball);
  camera_eye(g, &ball, &eye);
  g->pub.camera_x = eye.x;
  g->pub.camera_y = eye.y;
  g->pub.camera_z = eye.z;
}

void scene_draw(Gpu *gpu, const Game *g) {
  const TumbleContract *p = &g->pub;
  Vert ball, eye;
  ball_position(g, &ball);
  camera_eye(g, &ball, &eye);
  render_camera(eye.x, eye.y, eye.z, p->camera_angle);
  scene_sky(gpu);
  for (int y = 0; y < (int)p->map_height; ++y) {
    for (int x = 0; x < (int)p->map_width; ++x) {
      if (g->tile[y][x] == TILE_VOID) continue;
      draw_tile(gpu, g, x, y);
      if (g->tile[y][x] == TILE_SPIKES) draw_spikes(gpu, x, y);
      if (g->item[y][x] != ITEM_NONE) draw_item(gpu, g, x, y);
      /* The open exit's beacon; gone once the ball stands on it, so it does not cover the ball. */
      if (g->tile[y][x] == TILE_EXIT && p->keys_held >= p->keys_needed && p->state != STATE_SUCCESS) {
        Vert at = {x * TILE + TILE / 2, 120, y * TILE + TILE / 2};
        billboard_diamond(gpu, at, 30, 90, gpu_rgb(200, 255, 200), gpu_rgb(0, 160, 40), 1);
      }
    }
  }
  if (!(p->state == STATE_FALLEN && p->state_timer > 60)) draw_ball(gpu, g, &ball);
}
