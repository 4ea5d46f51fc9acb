/* A synthetic Kula World RAM trace, for testing games/kula without the game. It writes the seed's
   Table 3.2 variables at Kula World's addresses the way the seed describes the game changing
   them (§2.4, §3.2.4): the state code goes to 48 when the level starts; while a move runs the
   camera variable changes every frame; an item's score is added a few points per frame after the
   ball lands; rolling off the platform is state 6, reaching the exit state 20. Timings (frames):
   FORWARD 20, LOOKRIGHT/LOOKLEFT 15, JUMPFORWARD 40 (two squares); then the score count-up at 50
   points a frame (coin 250, fruit 500, key 1000). The level is tests/data/kula_trace/level01.txt.
   It uses no BIOS calls: VBlank is polled in I_STAT and the pad read through SIO0 directly. */
#include <stdint.h>

#define KULA(offset) (*(volatile uint32_t *)(0x80000000u + (offset)))
#define TIME KULA(0xA2E90)
#define CAMERA KULA(0xA5498)
#define SCORE KULA(0xA3E84)
#define STATE KULA(0xA2ADC)

#define I_STAT (*(volatile uint32_t *)0xBF801070)
#define I_MASK (*(volatile uint32_t *)0xBF801074)
#define JOY_DATA (*(volatile uint8_t *)0xBF801040)
#define JOY_STAT (*(volatile uint32_t *)0xBF801044)
#define JOY_MODE (*(volatile uint16_t *)0xBF801048)
#define JOY_CTRL (*(volatile uint16_t *)0xBF80104A)
#define JOY_BAUD (*(volatile uint16_t *)0xBF80104E)

#define PAD_UP (1u << 4)
#define PAD_RIGHT (1u << 5)
#define PAD_LEFT (1u << 7)
#define PAD_CROSS (1u << 14)

static const char *const map[] = {".E.", "#c#", "#f#", "#k#", "#S#"};
enum { W = 3, H = 5 };

static void wait_vblank(void) {
  I_STAT = ~1u;
  for (uint32_t spin = 0; !(I_STAT & 1u) && spin < 200000u; ++spin) {
  }
}

static uint8_t xfer(uint8_t b) {
  JOY_DATA = b;
  for (int i = 0; i < 100000 && !(JOY_STAT & 2); ++i) {
  }
  for (volatile int i = 0; i < 200; ++i) {
  }
  return JOY_DATA;
}

/* Digital pad read (psx-spx "Controllers - Communication Sequence"): 01h 42h 00h 00h 00h; the
   last two replies are the switches, active low. */
static uint32_t read_pad(void) {
  JOY_CTRL = 0x1003;
  for (volatile int i = 0; i < 200; ++i) {
  }
  xfer(0x01);
  xfer(0x42);
  xfer(0x00);
  uint32_t lo = xfer(0x00), hi = xfer(0x00);
  JOY_CTRL = 0;
  return ~(lo | hi << 8) & 0xFFFFu;
}

int main(void) {
  static const int dx[4] = {0, 1, 0, -1}, dy[4] = {-1, 0, 1, 0};
  I_MASK = 0;
  JOY_CTRL = 0x40;
  JOY_MODE = 0x000D;
  JOY_BAUD = 0x0088;
  JOY_CTRL = 0;
  STATE = 50; /* main menu */
  SCORE = 0;
  CAMERA = 0;
  TIME = 60 * 50;
  int x = 1, y = 4, facing = 0, frame = 0;
  int move = -1, move_frame = 0, length = 0, count_up = 0;
  uint32_t previous = 0;
  for (;;) {
    wait_vblank();
    uint32_t pad = read_pad(), pressed = pad & ~previous;
    previous = pad;
    if (++frame == 10) STATE = 48; /* the level starts */
    if (STATE != 48) continue;
    if (TIME) TIME = TIME - 1;
    if (!TIME) STATE = 4;
    if (count_up) {
      SCORE = SCORE + 50;
      --count_up;
      continue;
    }
    if (move < 0 && pressed) {
      move = pressed & PAD_UP ? (pad & PAD_CROSS ? 3 : 0) : pressed & PAD_RIGHT ? 1 : pressed & PAD_LEFT ? 2 : -1;
      move_frame = 0;
      length = move == 0 ? 20 : move == 3 ? 40 : 15;
    }
    if (move < 0) continue;
    CAMERA = CAMERA + (move == 0 ? 7 : move == 3 ? 5 : 11);
    if (++move_frame < length) continue;
    if (move == 1) facing = (facing + 1) & 3;
    if (move == 2) facing = (facing + 3) & 3;
    if (move == 0 || move == 3) {
      int n = move == 3 ? 2 : 1;
      x += n * dx[facing];
      y += n * dy[facing];
      char c = x < 0 || y < 0 || x >= W || y >= H ? '.' : map[y][x];
      if (c == '.') STATE = 6;
      if (c == 'E') STATE = 20;
      count_up = c == 'c' ? 5 : c == 'f' ? 10 : c == 'k' ? 20 : 0;
    }
    move = -1;
  }
}
