/* Rules of a level in play: starting a level, accepting moves, landing on tiles (items, exit,
   spikes, holes), crumbling tiles, the score count-up and the countdown clock. */
#include "game.h"
#include "moves.h"

static int on_map(const Game *g, int32_t x, int32_t y) {
  return x >= 0 && y >= 0 && (uint32_t)x < g->pub.map_width && (uint32_t)y < g->pub.map_height;
}

static uint8_t tile_at(const Game *g, int32_t x, int32_t y) {
  return on_map(g, x, y) ? g->tile[y][x] : TILE_VOID;
}

uint32_t game_random(Game *g) {
  uint32_t x = g->pub.rng ? g->pub.rng : 0x9E3779B9u; /* xorshift32 must not hold 0 */
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  g->pub.rng = x;
  return x;
}

static void set_state(Game *g, uint32_t state) {
  g->pub.state = state;
  g->pub.state_timer = 0;
  g->pub.move = MOVE_NONE;
  g->pub.move_frame = 0;
  g->pub.move_length = 0;
}

void game_start_level(Game *g, uint32_t number) {
  if (number < 1 || number > (uint32_t)tumble_level_count) return;
  const LevelDef *def = &tumble_levels[number - 1];
  TumbleContract *p = &g->pub;
  p->level = number;
  p->menu_level = number;
  p->map_width = def->width;
  p->map_height = def->height;
  p->keys_held = 0;
  p->keys_needed = 0;
  for (int y = 0; y < LEVEL_MAX_H; ++y) {
    for (int x = 0; x < LEVEL_MAX_W; ++x) {
      uint8_t tile = TILE_VOID, item = ITEM_NONE;
      if (x < def->width && y < def->height) level_decode_cell(def->cells[y * def->width + x], &tile, &item);
      g->tile[y][x] = tile;
      g->item[y][x] = item;
      g->crumble_timer[y][x] = 0;
      if (item == ITEM_KEY) ++p->keys_needed;
    }
  }
  p->score = 0;
  p->score_target = 0;
  p->clock = (uint32_t)def->time_seconds * 60;
  p->ball_x = def->start_x;
  p->ball_y = def->start_y;
  p->facing = def->start_facing;
  p->camera_angle = p->facing * ANGLE_QUARTER;
  g->rumble_frames = 0;
  set_state(g, STATE_PLAYING);
}

static void start_crumbling(Game *g, int32_t x, int32_t y) {
  if (tile_at(g, x, y) != TILE_CRUMBLE || g->crumble_timer[y][x]) return;
  g->crumble_timer[y][x] = (uint8_t)(FRAMES_CRUMBLE + (game_random(g) & 15));
  g->pub.events |= TUMBLE_EV_CRUMBLE_WARN;
  g->rumble_frames = 20;
}

int game_begin_move(Game *g, uint32_t move) {
  TumbleContract *p = &g->pub;
  if (p->state != STATE_PLAYING || p->move != MOVE_NONE) return 0;
  if (move < MOVE_FORWARD || move > MOVE_JUMP) return 0;
  int dx, dy, dist = move_distance(move);
  facing_step(p->facing, &dx, &dy);
  g->from_x = (int32_t)p->ball_x;
  g->from_y = (int32_t)p->ball_y;
  g->to_x = g->from_x + dx * dist;
  g->to_y = g->from_y + dy * dist;
  g->move_facing = p->facing;
  uint8_t item = on_map(g, g->to_x, g->to_y) && dist ? g->item[g->to_y][g->to_x] : ITEM_NONE;
  p->move = move;
  p->move_frame = 0;
  p->move_length = move_travel_frames(move) + move_item_frames(item);
  if (dist) start_crumbling(g, g->from_x, g->from_y);
  p->events |= move == MOVE_FORWARD ? TUMBLE_EV_ROLL : dist || move == MOVE_JUMP ? TUMBLE_EV_JUMP : TUMBLE_EV_TURN;
  return 1;
}

static void collect(Game *g, int32_t x, int32_t y) {
  TumbleContract *p = &g->pub;
  uint8_t item = g->item[y][x];
  if (item == ITEM_NONE) return;
  g->item[y][x] = ITEM_NONE;
  p->score_target += level_item_score(item);
  p->events |= item == ITEM_COIN ? TUMBLE_EV_COIN : item == ITEM_FRUIT ? TUMBLE_EV_FRUIT : TUMBLE_EV_KEY;
  if (item == ITEM_KEY && ++p->keys_held == p->keys_needed) p->events |= TUMBLE_EV_EXIT_OPEN;
}

/* The ball touches down on (to_x, to_y): the tile decides what happens. */
static void land(Game *g) {
  TumbleContract *p = &g->pub;
  p->ball_x = (uint32_t)g->to_x;
  p->ball_y = (uint32_t)g->to_y;
  p->events |= TUMBLE_EV_LAND;
  switch (tile_at(g, g->to_x, g->to_y)) {
    case TILE_VOID:
      p->events |= TUMBLE_EV_FALL;
      g->rumble_frames = 30;
      set_state(g, STATE_FALLEN);
      return;
    case TILE_SPIKES:
      p->events |= TUMBLE_EV_SPIKED;
      g->rumble_frames = 30;
      set_state(g, STATE_SPIKED);
      return;
    case TILE_EXIT:
      if (p->keys_held >= p->keys_needed) {
        p->score = p->score_target; /* the win screen shows the final score */
        p->events |= TUMBLE_EV_WIN;
        ++p->levels_completed;
        set_state(g, STATE_SUCCESS);
        return;
      }
      break;
    default:
      collect(g, g->to_x, g->to_y);
      break;
  }
}

static void advance_move(Game *g) {
  TumbleContract *p = &g->pub;
  ++p->move_frame;
  p->camera_angle = move_camera_angle(g->move_facing, p->move, p->move_frame);
  if (p->move_frame == move_travel_frames(p->move)) {
    p->facing = move_new_facing(g->move_facing, p->move);
    if (move_distance(p->move) || p->move == MOVE_JUMP) land(g);
    if (p->state != STATE_PLAYING) return;
  }
  if (p->move_frame >= p->move_length) {
    p->move = MOVE_NONE;
    p->move_frame = 0;
    p->move_length = 0;
  }
}

static int ball_resting_on(const Game *g, int32_t x, int32_t y) {
  const TumbleContract *p = &g->pub;
  int airborne = p->move != MOVE_NONE && p->move != MOVE_LOOK_LEFT && p->move != MOVE_LOOK_RIGHT;
  return !airborne && (int32_t)p->ball_x == x && (int32_t)p->ball_y == y;
}

static void update_crumbling(Game *g) {
  for (int32_t y = 0; y < (int32_t)g->pub.map_height; ++y) {
    for (int32_t x = 0; x < (int32_t)g->pub.map_width; ++x) {
      if (!g->crumble_timer[y][x] || --g->crumble_timer[y][x]) continue;
      g->tile[y][x] = TILE_VOID;
      g->pub.events |= TUMBLE_EV_CRUMBLE_BREAK;
      if (ball_resting_on(g, x, y) && g->pub.state == STATE_PLAYING) {
        g->pub.events |= TUMBLE_EV_FALL;
        set_state(g, STATE_FALLEN);
      }
    }
  }
}

void game_play_frame(Game *g) {
  TumbleContract *p = &g->pub;
  if (p->move != MOVE_NONE) advance_move(g);
  if (p->score < p->score_target) {
    uint32_t left = p->score_target - p->score;
    p->score += left < SCORE_STEP ? left : SCORE_STEP;
  }
  update_crumbling(g);
  if (p->state != STATE_PLAYING) return;
  if (p->clock && --p->clock == 0) {
    p->events |= TUMBLE_EV_TIME_UP;
    set_state(g, STATE_TIME_UP);
  }
}
