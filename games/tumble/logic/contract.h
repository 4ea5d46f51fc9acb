/* Tumble's RAM contract: the block of game variables that environments, tests and tools read (and
   the two they may write: request_level, rng). On the PlayStation it is the first member of the
   game state, which the linker script places at 0x80010000 (RAM offset 0x10000); README.md
   documents every field. Every field is a 32-bit word so a reader needs no struct packing. */
#ifndef TUMBLE_CONTRACT_H
#define TUMBLE_CONTRACT_H
#include <stdint.h>

#define TUMBLE_CONTRACT_ADDRESS 0x80010000u
#define TUMBLE_MAGIC 0x4C424D54u /* "TMBL" in little-endian byte order */
#define TUMBLE_CONTRACT_VERSION 2u

/* Game state codes, in the spirit of the Kula World codes in the seed's Appendix B (same numbers
   where Kula has the state). */
enum TumbleState {
  STATE_BOOT = 0,
  STATE_SPIKED = 2,
  STATE_TIME_UP = 4,
  STATE_FALLEN = 6,
  STATE_GAME_OVER = 18,
  STATE_SUCCESS = 20,
  STATE_PLAYING = 48,
  STATE_TITLE = 50,
  STATE_LEVEL_SELECT = 56
};

/* Moves (the seed's actions 0..3 are FORWARD, LOOK RIGHT, LOOK LEFT, JUMP FORWARD; stored here
   plus one so that 0 means "no move in progress"). */
enum TumbleMove {
  MOVE_NONE = 0,
  MOVE_FORWARD = 1,
  MOVE_LOOK_RIGHT = 2,
  MOVE_LOOK_LEFT = 3,
  MOVE_JUMP_FORWARD = 4,
  MOVE_JUMP = 5
};

/* Facing directions: north is up the map file (row decreasing). */
enum TumbleFacing { FACING_NORTH = 0, FACING_EAST = 1, FACING_SOUTH = 2, FACING_WEST = 3 };

typedef struct TumbleContract {
  uint32_t magic;            /* 0x00 TUMBLE_MAGIC once the game has initialised */
  uint32_t version;          /* 0x04 TUMBLE_CONTRACT_VERSION */
  uint32_t state;            /* 0x08 enum TumbleState */
  uint32_t score;            /* 0x0C score shown, counts up to score_target over several frames */
  uint32_t score_target;     /* 0x10 score including items whose count-up is still running */
  uint32_t clock;            /* 0x14 time left in frames (60 per second) */
  uint32_t camera_angle;     /* 0x18 view yaw, 0..4095 = 0..360 deg, north 0, east 1024 */
  uint32_t ball_x;           /* 0x1C column of the ball's tile (updated when a move lands) */
  uint32_t ball_y;           /* 0x20 row of the ball's tile */
  uint32_t facing;           /* 0x24 enum TumbleFacing */
  uint32_t level;            /* 0x28 current level, 1-based (0 before the first level) */
  uint32_t keys_held;        /* 0x2C */
  uint32_t keys_needed;      /* 0x30 keys on the level; the exit opens when keys_held == this */
  uint32_t levels_completed; /* 0x34 levels won since power-on */
  uint32_t move;             /* 0x38 enum TumbleMove in progress, MOVE_NONE when idle */
  uint32_t move_frame;       /* 0x3C frames of the current move done so far */
  uint32_t move_length;      /* 0x40 frames the current move lasts */
  uint32_t rng;              /* 0x44 random generator state (xorshift32); write to reseed */
  uint32_t request_level;    /* 0x48 write N (1..level_count) to start level N; game clears it */
  uint32_t frame;            /* 0x4C frames since power-on */
  uint32_t level_count;      /* 0x50 number of levels in the program */
  uint32_t events;           /* 0x54 TUMBLE_EV_* bits raised during the latest frame */
  uint32_t menu_level;       /* 0x58 level highlighted on the level-select screen */
  uint32_t map_width;        /* 0x5C current level's map size in tiles */
  uint32_t map_height;       /* 0x60 */
  uint32_t state_timer;      /* 0x64 frames spent in the current state */
  int32_t camera_x;          /* 0x68 camera eye position in world units (256 per tile); it */
  int32_t camera_y;          /* 0x6C follows the ball every frame of a move, like the seed's */
  int32_t camera_z;          /* 0x70 Kula World camera position (version 2) */
} TumbleContract;

/* Event bits (TumbleContract.events): what happened this frame, for sound, rumble and agents. */
#define TUMBLE_EV_ROLL (1u << 0)
#define TUMBLE_EV_TURN (1u << 1)
#define TUMBLE_EV_JUMP (1u << 2)
#define TUMBLE_EV_COIN (1u << 3)
#define TUMBLE_EV_FRUIT (1u << 4)
#define TUMBLE_EV_KEY (1u << 5)
#define TUMBLE_EV_EXIT_OPEN (1u << 6)
#define TUMBLE_EV_WIN (1u << 7)
#define TUMBLE_EV_FALL (1u << 8)
#define TUMBLE_EV_SPIKED (1u << 9)
#define TUMBLE_EV_TIME_UP (1u << 10)
#define TUMBLE_EV_CRUMBLE_WARN (1u << 11)
#define TUMBLE_EV_CRUMBLE_BREAK (1u << 12)
#define TUMBLE_EV_MENU (1u << 13)
#define TUMBLE_EV_LAND (1u << 14)

#endif
