/* Controller in port 1 read directly through the SIO0 registers (psx-spx "Controllers and
   Memory Cards"): the 42h poll each frame, and DualShock rumble set up through config mode (43h
   enter, 4Dh map motors, 43h exit). No BIOS pad functions. */
#ifndef TUMBLE_PAD_H
#define TUMBLE_PAD_H
#include <stdint.h>

typedef struct Pad {
  uint32_t buttons;  /* PAD_* bits, 1 = pressed */
  uint8_t id;        /* low byte of the pad's ID (41h digital, 73h analog), 0 if none answered */
  uint8_t rumble_ready;
} Pad;

void pad_init(Pad *pad);
/* Polls port 1; `rumble` is the large-motor speed (0 = off) sent to a DualShock. Returns the held
   buttons (0 when no pad answers). */
uint32_t pad_poll(Pad *pad, uint8_t rumble);

#endif
