/* Pad protocol through the SIO0 registers, no BIOS (psx-spx "Controllers - Communication
   Sequence", "Controllers - Rumble Configuration"). Needs the digital pad in port 1 and a
   DualShock in port 2 (psxrl run --pad2 dualshock), no memory cards. */
#include "sio_port.h"

static void digital_pad(void) {
  static const uint8_t tx[] = {0x01, 0x42, 0x00, 0x00, 0x00};
  static const uint8_t rx[] = {0xFF, 0x41, 0x5A, 0xFF, 0xFF}; /* ID 5A41h, nothing pressed */
  expect_command("digital read", 1, tx, rx, 5);
}

static void status_idle(void) {
  /* TX ready 1 and 2, RX empty, /ACK high, no IRQ. */
  CHECK_EQ("JOY_STAT idle", JOY_STAT & 0x2FF, 0x005);
}

static void empty_card_slot(void) {
  int ack;
  sio_select(1);
  uint8_t r = sio_xfer(0x81, &ack);
  sio_deselect();
  CHECK_EQ("no card: Hi-Z", r, 0xFF);
  CHECK_EQ("no card: no /ACK", ack, 0);
}

static void dualshock(void) {
  static const uint8_t read5[] = {0x01, 0x42, 0x00, 0x00, 0x00};
  static const uint8_t digital[] = {0xFF, 0x41, 0x5A, 0xFF, 0xFF};
  expect_command("dualshock digital read", 2, read5, digital, 5);

  static const uint8_t enter[] = {0x01, 0x43, 0x00, 0x01, 0x00};
  expect_command("enter config (normal-mode reply)", 2, enter, digital, 5);

  static const uint8_t set_analog[] = {0x01, 0x44, 0x00, 0x01, 0x03, 0x00, 0x00, 0x00, 0x00};
  static const uint8_t zeros[] = {0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  expect_command("44h analog+lock", 2, set_analog, zeros, 9);

  static const uint8_t get_led[] = {0x01, 0x45, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  static const uint8_t led_on[] = {0xFF, 0xF3, 0x5A, 0x01, 0x02, 0x01, 0x02, 0x01, 0x00};
  expect_command("45h LED on", 2, get_led, led_on, 9);

  static const uint8_t var_a[] = {0x01, 0x46, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00};
  static const uint8_t var_a_rx[] = {0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x01, 0x01, 0x01, 0x14};
  expect_command("46h index 1", 2, var_a, var_a_rx, 9);

  static const uint8_t g47[] = {0x01, 0x47, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  static const uint8_t g47_rx[] = {0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x02, 0x00, 0x01, 0x00};
  expect_command("47h", 2, g47, g47_rx, 9);

  static const uint8_t var_b[] = {0x01, 0x4C, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00};
  static const uint8_t var_b_rx[] = {0xFF, 0xF3, 0x5A, 0x00, 0x00, 0x00, 0x07, 0x00, 0x00};
  expect_command("4Ch index 1", 2, var_b, var_b_rx, 9);

  /* Motor mapping: first reply shows the power-up FFh x6, the second the mapping just set. */
  static const uint8_t map[] = {0x01, 0x4D, 0x00, 0x00, 0x01, 0xFF, 0xFF, 0xFF, 0xFF};
  static const uint8_t map_old[] = {0xFF, 0xF3, 0x5A, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
  static const uint8_t map_new[] = {0xFF, 0xF3, 0x5A, 0x00, 0x01, 0xFF, 0xFF, 0xFF, 0xFF};
  expect_command("4Dh first", 2, map, map_old, 9);
  expect_command("4Dh again", 2, map, map_new, 9);

  static const uint8_t exit_cfg[] = {0x01, 0x43, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  expect_command("exit config", 2, exit_cfg, zeros, 9);

  /* Analog mode: ID 5A73h, switches, sticks centred at 80h; bytes 3/4 drive the motors. */
  static const uint8_t rumble[] = {0x01, 0x42, 0x00, 0x01, 0xC0, 0x00, 0x00, 0x00, 0x00};
  static const uint8_t analog[] = {0xFF, 0x73, 0x5A, 0xFF, 0xFF, 0x80, 0x80, 0x80, 0x80};
  expect_command("analog read with rumble", 2, rumble, analog, 9);
  static const uint8_t stop[] = {0x01, 0x42, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  expect_command("analog read, motors off", 2, stop, analog, 9);

  /* Config commands are refused outside config mode: no /ACK after the command byte. */
  int acks[3];
  uint8_t rx[3];
  static const uint8_t bad[] = {0x01, 0x45, 0x00};
  sio_command(2, bad, rx, acks, 3);
  CHECK_EQ("45h outside config: /ACK on 01h", acks[0], 1);
  CHECK_EQ("45h outside config: no /ACK", acks[1], 0);
}

int main(void) {
  sio_init();
  status_idle();
  digital_pad();
  empty_card_slot();
  dualshock();
  status_idle();
  return test_done("sio_pad");
}
