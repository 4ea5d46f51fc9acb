/* Move timings and in-between positions (see moves.h). */
#include "moves.h"
#include "level.h"

uint32_t move_travel_frames(uint32_t move) {
  switch (move) {
    case MOVE_FORWARD: return FRAMES_FORWARD;
    case MOVE_LOOK_LEFT:
    case MOVE_LOOK_RIGHT: return FRAMES_LOOK;
    case MOVE_JUMP_FORWARD: return FRAMES_JUMP_FORWARD;
    case MOVE_JUMP: return FRAMES_JUMP;
    default: return 0;
  }
}

uint32_t move_item_frames(uint8_t item) {
  uint32_t value = level_item_score(item);
  return value ? value / SCORE_STEP + 2 : 0;
}

int move_distance(uint32_t move) {
  if (move == MOVE_FORWARD) return 1;
  if (move == MOVE_JUMP_FORWARD) return 2;
  return 0;
}

void facing_step(uint32_t facing, int *dx, int *dy) {
  static const int8_t step_x[4] = {0, 1, 0, -1};
  static const int8_t step_y[4] = {-1, 0, 1, 0};
  *dx = step_x[facing & 3];
  *dy = step_y[facing & 3];
}

uint32_t move_new_facing(uint32_t facing, uint32_t move) {
  if (move == MOVE_LOOK_RIGHT) return (facing + 1) & 3;
  if (move == MOVE_LOOK_LEFT) return (facing + 3) & 3;
  return facing;
}

uint32_t move_camera_angle(uint32_t facing, uint32_t move, uint32_t frame) {
  uint32_t base = facing * ANGLE_QUARTER;
  if (move != MOVE_LOOK_LEFT && move != MOVE_LOOK_RIGHT) return base;
  uint32_t done = frame >= FRAMES_LOOK ? ANGLE_QUARTER : frame * ANGLE_QUARTER / FRAMES_LOOK;
  return (move == MOVE_LOOK_RIGHT ? base + done : base + ANGLE_FULL - done) % ANGLE_FULL;
}

uint32_t move_travel_progress(uint32_t move, uint32_t frame) {
  uint32_t travel = move_travel_frames(move);
  if (travel == 0 || frame >= travel) return 256;
  return frame * 256 / travel;
}

uint32_t move_jump_height(uint32_t move, uint32_t frame) {
  if (move != MOVE_JUMP && move != MOVE_JUMP_FORWARD) return 0;
  uint32_t t = move_travel_progress(move, frame);
  /* Parabola 4*t*(1-t), peaking at 3/4 of a tile (192/256). */
  return 3 * t * (256 - t) / 256;
}
