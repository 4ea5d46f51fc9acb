/* The whole state of a Tumble game and the per-frame entry point. The public RAM contract is the
   first member, so on the PlayStation the contract's fixed address is the game's address. The
   rules (rules.c) play a level; the flow (flow.c) runs the screens around it. Neither touches
   hardware: the same code runs on the PlayStation and in the host unit tests. */
#ifndef TUMBLE_GAME_H
#define TUMBLE_GAME_H
#include <stdint.h>
#include "contract.h"
#include "level.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Pad buttons as the PlayStation digital pad reports them (bit set = pressed, after inverting the
   pad's active-low bytes). */
#define PAD_SELECT (1u << 0)
#define PAD_START (1u << 3)
#define PAD_UP (1u << 4)
#define PAD_RIGHT (1u << 5)
#define PAD_DOWN (1u << 6)
#define PAD_LEFT (1u << 7)
#define PAD_TRIANGLE (1u << 12)
#define PAD_CIRCLE (1u << 13)
#define PAD_CROSS (1u << 14)
#define PAD_SQUARE (1u << 15)

/* Frames the lost screens (spiked, fallen, time up) show before game over, and the level-complete
   screen before the next level. */
#define FRAMES_LOST_SCREEN 120
#define FRAMES_SUCCESS_SCREEN 150
/* Crumbling tiles break this many frames (plus 0..15 random) after the ball leaves them. */
#define FRAMES_CRUMBLE 45

typedef struct Game {
  TumbleContract pub; /* must stay first: the RAM contract */
  uint8_t tile[LEVEL_MAX_H][LEVEL_MAX_W];
  uint8_t item[LEVEL_MAX_H][LEVEL_MAX_W];
  uint8_t crumble_timer[LEVEL_MAX_H][LEVEL_MAX_W]; /* 0 = not crumbling */
  int32_t from_x, from_y;  /* tile the current move started on */
  int32_t to_x, to_y;      /* tile it lands on */
  uint32_t move_facing;    /* facing when the current move started */
  uint32_t pad_previous;   /* buttons held last frame, for press edges */
  uint32_t wait_release;   /* 1: a level started by a button press takes no move until every
                              button is up (the confirming Cross is not a jump) */
  uint32_t rumble_frames;  /* frames of rumble still wanted (crumble warnings, deaths) */
} Game;

/* Power-on: title screen, random generator seeded with `seed`. */
void game_init(Game *g, uint32_t seed);
/* Starts level `number` (1-based); out-of-range numbers are ignored. */
void game_start_level(Game *g, uint32_t number);
/* Runs one frame (1/60 s) of the game with the buttons currently held. */
void game_frame(Game *g, uint32_t buttons);

/* Rules of a level in play (rules.c). */
int game_begin_move(Game *g, uint32_t move); /* 1 if accepted: playing and no move running */
void game_play_frame(Game *g);
/* Next value of the xorshift32 generator kept in the contract. */
uint32_t game_random(Game *g);

#ifdef __cplusplus
}
#endif

#endif
