/* SIO0 controller access (see pad.h). A transfer: select the port (JOY_CTRL /JOYn output), send
   bytes one at a time, reading each reply from the RX FIFO, and wait for the pad's /ACK pulse
   (seen as JOY_STAT bit 9 with the ACK interrupt enabled) before the next byte; a missing ACK
   ends the transfer (no pad, or its last byte). */
#include "pad.h"
#include "game.h"
#include "hw.h"

#define CTRL_TXEN 0x0001
#define CTRL_SELECT 0x0002
#define CTRL_ACK 0x0010
#define CTRL_RESET 0x0040
#define CTRL_ACK_IRQ 0x1000
#define STAT_TX_READY 0x0001
#define STAT_RX_NOT_EMPTY 0x0002
#define STAT_IRQ 0x0200

static void delay(uint32_t n) {
  for (volatile uint32_t i = 0; i < n; ++i) {
  }
}

/* Sends one byte, returns the reply in *in; returns 1 if the pad acknowledged (more follows). */
static int exchange(uint8_t out, uint8_t *in, int want_ack) {
  for (uint32_t spin = 0; !(JOY_STAT & STAT_TX_READY) && spin < 10000; ++spin) {
  }
  JOY_DATA = out;
  uint32_t spin = 0;
  while (!(JOY_STAT & STAT_RX_NOT_EMPTY) && spin < 10000) ++spin;
  *in = spin < 10000 ? JOY_DATA : 0xFF;
  if (!want_ack) return 0;
  for (spin = 0; !(JOY_STAT & STAT_IRQ) && spin < 10000; ++spin) {
  }
  int acked = (JOY_STAT & STAT_IRQ) != 0;
  JOY_CTRL = JOY_CTRL | CTRL_ACK;  /* acknowledge the SIO0 interrupt flag */
  I_STAT = ~IRQ_CONTROLLER;
  return acked;
}

/* One command to port 1: sends `n` bytes from `out` (replies into `in`), stopping early when the
   pad stops acknowledging. Returns the number of bytes exchanged. */
static int transfer(const uint8_t *out, uint8_t *in, int n) {
  JOY_CTRL = CTRL_TXEN | CTRL_SELECT | CTRL_ACK_IRQ;
  delay(200);
  int i = 0;
  while (i < n) {
    int more = exchange(out[i], &in[i], i + 1 < n);
    ++i;
    if (!more) break;
  }
  JOY_CTRL = 0;
  delay(200);
  return i;
}

static void configure_rumble(Pad *pad) {
  static const uint8_t enter[9] = {0x01, 0x43, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00};
  static const uint8_t motors[9] = {0x01, 0x4D, 0x00, 0x00, 0x01, 0xFF, 0xFF, 0xFF, 0xFF};
  static const uint8_t leave[9] = {0x01, 0x43, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  uint8_t reply[9];
  transfer(enter, reply, 9);
  if (reply[1] != 0xF3) return;  /* no config mode: not a DualShock */
  transfer(motors, reply, 9);
  transfer(leave, reply, 9);
  pad->rumble_ready = 1;
}

void pad_init(Pad *pad) {
  pad->buttons = 0;
  pad->id = 0;
  pad->rumble_ready = 0;
  JOY_CTRL = CTRL_RESET;
  JOY_MODE = 0x000D;  /* baud factor 1, 8 data bits, no parity */
  JOY_BAUD = 0x0088;  /* 250 kHz */
  JOY_CTRL = 0;
  configure_rumble(pad);
}

uint32_t pad_poll(Pad *pad, uint8_t rumble) {
  uint8_t out[9] = {0x01, 0x42, 0x00, 0x00, rumble, 0x00, 0x00, 0x00, 0x00};
  uint8_t in[9] = {0};
  int n = transfer(out, in, 9);
  uint8_t id = in[1];
  if (n < 5 || in[2] != 0x5A || id == 0xFF) {
    pad->id = 0;
    pad->rumble_ready = 0;
    pad->buttons = 0;
    return 0;
  }
  if (pad->id == 0) {
    pad->id = id;
    configure_rumble(pad);
  }
  pad->buttons = (uint32_t)(uint16_t)~(in[3] | in[4] << 8);
  return pad->buttons;
}
