/* GTE camera and projection for Tumble (see render.h, gte.h). */
#include "render.h"
#include "gpu.h"
#include "gte.h"

/* Camera pitch: 30 degrees down (cos = 3547/4096, sin = 2048/4096). */
#define PITCH_COS 3547
#define PITCH_SIN 2048

/* Bhaskara I's approximation sin x ~ 16x(pi-x) / (5pi^2 - 4x(pi-x)) with pi = 2048 angle units,
   scaled to 4.12 (max error about 0.2%): 4096 * 16u / (5*2048^2 - 4u), u = a(2048 - a),
   rearranged to stay within 32 bits. */
int32_t fx_sin(uint32_t angle) {
  angle &= 4095;
  int negative = angle >= 2048;
  uint32_t a = angle & 2047;
  uint32_t u = a * (2048 - a);
  int32_t s = (int32_t)((u << 10) / ((5242880u - u) >> 4));
  return negative ? -s : s;
}

int32_t fx_cos(uint32_t angle) { return fx_sin(angle + 1024); }

void render_camera(int32_t x, int32_t y, int32_t z, uint32_t yaw) {
  int32_t s = fx_sin(yaw), c = fx_cos(yaw);
  /* Rows: camera right, camera down, camera forward (see README "View"). */
  int32_t m[3][3] = {
    {c, 0, s},
    {-(s * PITCH_SIN) >> 12, -PITCH_COS, (c * PITCH_SIN) >> 12},
    {(s * PITCH_COS) >> 12, -PITCH_SIN, -(c * PITCH_COS) >> 12},
  };
  gte_ctc2((m[0][0] & 0xFFFF) | (uint32_t)m[0][1] << 16, 0);
  gte_ctc2((m[0][2] & 0xFFFF) | (uint32_t)m[1][0] << 16, 1);
  gte_ctc2((m[1][1] & 0xFFFF) | (uint32_t)m[1][2] << 16, 2);
  gte_ctc2((m[2][0] & 0xFFFF) | (uint32_t)m[2][1] << 16, 3);
  gte_ctc2(m[2][2], 4);
  for (int r = 0; r < 3; ++r) {
    int32_t t = -((m[r][0] * x + m[r][1] * y + m[r][2] * z) >> 12);
    if (r == 0) gte_ctc2(t, 5);
    if (r == 1) gte_ctc2(t, 6);
    if (r == 2) gte_ctc2(t, 7);
  }
  gte_ctc2((SCREEN_W / 2) << 16, 24);
  gte_ctc2((SCREEN_H / 2) << 16, 25);
  gte_ctc2(PROJ_H, 26);
  gte_ctc2(4096 / (3 * 8), 29);
  gte_ctc2(4096 / (4 * 8), 30);
}

static int clamp_ot(int32_t otz) { return otz < 1 ? 1 : otz >= OT_LEN - 1 ? OT_LEN - 2 : otz; }

static Screen unpack(uint32_t sxy, uint32_t sz) {
  Screen s;
  s.x = (int16_t)(sxy & 0xFFFF);
  s.y = (int16_t)(sxy >> 16);
  s.z = (int32_t)(sz & 0xFFFF);
  return s;
}

static int usable(const Screen *s) {
  return s->z >= NEAR_Z && s->x > -900 && s->x < 900 && s->y > -900 && s->y < 900;
}

int render_project3(const Vert v[3], Screen out[3]) {
  gte_load_v0(v[0].x, v[0].y, v[0].z);
  gte_load_v1(v[1].x, v[1].y, v[1].z);
  gte_load_v2(v[2].x, v[2].y, v[2].z);
  gte_cmd(GTE_RTPT);
  out[0] = unpack(gte_mfc2(12), gte_mfc2(17));
  out[1] = unpack(gte_mfc2(13), gte_mfc2(18));
  out[2] = unpack(gte_mfc2(14), gte_mfc2(19));
  return usable(&out[0]) && usable(&out[1]) && usable(&out[2]);
}

int render_project1(const Vert *v, Screen *out) {
  gte_load_v0(v->x, v->y, v->z);
  gte_cmd(GTE_RTPS);
  *out = unpack(gte_mfc2(14), gte_mfc2(19));
  return usable(out);
}

int32_t render_nclip(void) {
  gte_cmd(GTE_NCLIP);
  return (int32_t)gte_mfc2(24);
}

int render_ot_z(int32_t sz) { return clamp_ot(sz >> 3); }

int render_avsz3(void) {
  gte_cmd(GTE_AVSZ3);
  return clamp_ot((int32_t)(gte_mfc2(7) & 0xFFFF));
}

int render_avsz4(void) {
  gte_cmd(GTE_AVSZ4);
  return clamp_ot((int32_t)(gte_mfc2(7) & 0xFFFF));
}
