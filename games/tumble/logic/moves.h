/* Moves: how long each lasts, where it takes the ball, and how the view and the ball travel while
   it runs (the rules use the lengths and destinations, the renderer the in-between positions). */
#ifndef TUMBLE_MOVES_H
#define TUMBLE_MOVES_H
#include <stdint.h>
#include "contract.h"
#ifdef __cplusplus
extern "C" {
#endif

#define FRAMES_FORWARD 16
#define FRAMES_LOOK 12
#define FRAMES_JUMP_FORWARD 36
#define FRAMES_JUMP 28
/* The score counts up by this much per frame after an item is collected. */
#define SCORE_STEP 50
/* Frames a quarter turn of the view is worth in camera_angle units (4096 = full turn). */
#define ANGLE_QUARTER 1024
#define ANGLE_FULL 4096

/* Frames from the start of a move until the ball lands (or the turn completes). */
uint32_t move_travel_frames(uint32_t move);
/* Extra frames a move lasts when it collects `item` (the count-up of its score plus a pause). */
uint32_t move_item_frames(uint8_t item);
/* Tiles the move carries the ball along its facing: 1 (forward), 2 (jump forward) or 0. */
int move_distance(uint32_t move);
/* Unit step on the map for a facing direction (north is row - 1). */
void facing_step(uint32_t facing, int *dx, int *dy);
/* Facing after a move (turns change it, other moves keep it). */
uint32_t move_new_facing(uint32_t facing, uint32_t move);
/* View yaw `frame` frames into `move` that started facing `facing` (0..4095). */
uint32_t move_camera_angle(uint32_t facing, uint32_t move, uint32_t frame);
/* Progress of the ball from its start tile toward its landing tile, 0..256. */
uint32_t move_travel_progress(uint32_t move, uint32_t frame);
/* Height of the ball above the floor for a jump, in 1/256 tile units. */
uint32_t move_jump_height(uint32_t move, uint32_t frame);

#ifdef __cplusplus
}
#endif

#endif
