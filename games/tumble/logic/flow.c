/* The screens around a level: title, level select, level in play, the lost screens (spiked, fallen,
   time up), level complete and game over; pad buttons become moves or menu choices here, and the
   contract's request_level starts a level from any screen. */
#include "game.h"
#include "moves.h"

void game_init(Game *g, uint32_t seed) {
  uint8_t *bytes = (uint8_t *)g;
  for (uint32_t i = 0; i < sizeof *g; ++i) bytes[i] = 0;
  g->pub.magic = TUMBLE_MAGIC;
  g->pub.version = TUMBLE_CONTRACT_VERSION;
  g->pub.rng = seed;
  g->pub.level_count = (uint32_t)tumble_level_count;
  g->pub.menu_level = 1;
  g->pub.state = STATE_TITLE;
}

static uint32_t move_from_buttons(uint32_t held) {
  if (held & PAD_CROSS) return held & PAD_UP ? MOVE_JUMP_FORWARD : MOVE_JUMP;
  if (held & PAD_UP) return MOVE_FORWARD;
  if (held & PAD_LEFT) return MOVE_LOOK_LEFT;
  if (held & PAD_RIGHT) return MOVE_LOOK_RIGHT;
  return MOVE_NONE;
}

static void enter(Game *g, uint32_t state) {
  g->pub.state = state;
  g->pub.state_timer = 0;
  g->pub.events |= TUMBLE_EV_MENU;
}

/* Starts a level chosen with the pad: the button that chose it must be let go before it moves. */
static void start_by_pad(Game *g, uint32_t number) {
  game_start_level(g, number);
  g->wait_release = 1;
}

static void level_select(Game *g, uint32_t pressed) {
  TumbleContract *p = &g->pub;
  uint32_t n = p->level_count;
  if (pressed & (PAD_RIGHT | PAD_UP)) {
    p->menu_level = p->menu_level % n + 1;
    p->events |= TUMBLE_EV_MENU;
  } else if (pressed & (PAD_LEFT | PAD_DOWN)) {
    p->menu_level = (p->menu_level + n - 2) % n + 1;
    p->events |= TUMBLE_EV_MENU;
  } else if (pressed & (PAD_START | PAD_CROSS)) {
    start_by_pad(g, p->menu_level);
  } else if (pressed & PAD_TRIANGLE) {
    enter(g, STATE_TITLE);
  }
}

static void after_success(Game *g, uint32_t pressed) {
  TumbleContract *p = &g->pub;
  if (p->state_timer < FRAMES_SUCCESS_SCREEN && !(p->state_timer >= 30 && (pressed & PAD_START))) return;
  if (p->level >= p->level_count) {
    enter(g, STATE_GAME_OVER);
  } else if (p->state_timer < FRAMES_SUCCESS_SCREEN) {
    start_by_pad(g, p->level + 1); /* Start pressed */
  } else {
    game_start_level(g, p->level + 1);
    g->wait_release = 0;
  }
}

void game_frame(Game *g, uint32_t buttons) {
  TumbleContract *p = &g->pub;
  uint32_t pressed = buttons & ~g->pad_previous;
  g->pad_previous = buttons;
  p->events = 0;
  ++p->frame;
  if (g->rumble_frames) --g->rumble_frames;
  if (p->request_level) {
    uint32_t level = p->request_level;
    p->request_level = 0;
    if (level <= p->level_count) {
      game_start_level(g, level);
      g->wait_release = 0;
      return;
    }
  }
  ++p->state_timer;
  switch (p->state) {
    case STATE_TITLE:
      if (pressed & (PAD_START | PAD_CROSS)) enter(g, STATE_LEVEL_SELECT);
      break;
    case STATE_LEVEL_SELECT: level_select(g, pressed); break;
    case STATE_PLAYING:
      game_play_frame(g);
      if (!buttons) g->wait_release = 0;
      if (p->move == MOVE_NONE && !g->wait_release) game_begin_move(g, move_from_buttons(buttons));
      break;
    case STATE_SPIKED:
    case STATE_FALLEN:
    case STATE_TIME_UP:
      if (p->state_timer >= FRAMES_LOST_SCREEN) enter(g, STATE_GAME_OVER);
      break;
    case STATE_SUCCESS: after_success(g, pressed); break;
    case STATE_GAME_OVER:
      if (p->state_timer >= 30 && (pressed & (PAD_START | PAD_CROSS))) enter(g, STATE_TITLE);
      break;
    default: enter(g, STATE_TITLE); break;
  }
}
