/* BIOS-free access to the controller/memory card port SIO0 (psx-spx "Controller and Memory Card
   I/O Ports") for the sio_* test programs: reset, slot select, and byte exchanges that report
   whether the device answered with /ACK (IRQ7 in I_STAT, polled with interrupts masked). */
#ifndef SIO_PORT_H
#define SIO_PORT_H
#include <stdint.h>

#include "psx/test.h"

#define JOY_DATA (*(volatile uint8_t *)0xBF801040)
#define JOY_STAT (*(volatile uint32_t *)0xBF801044)
#define JOY_MODE (*(volatile uint16_t *)0xBF801048)
#define JOY_CTRL (*(volatile uint16_t *)0xBF80104A)
#define JOY_BAUD (*(volatile uint16_t *)0xBF80104E)
#define I_STAT (*(volatile uint32_t *)0xBF801070)
#define I_MASK (*(volatile uint32_t *)0xBF801074)
#define IRQ_PAD (1u << 7)

/* Loop counts: far beyond the ~31000-cycle late memory card /ACK, bounded so that a missing
   device fails a check instead of hanging. */
#define RX_TIMEOUT 100000
#define ACK_TIMEOUT 20000

static void delay(int n) {
  for (volatile int i = 0; i < n; ++i) {
  }
}

/* JOY_CTRL reset, then the kernel's usual setup: 8 bits no parity MUL1, 250 kHz. */
static void sio_init(void) {
  I_MASK = 0;
  JOY_CTRL = 0x40;
  JOY_MODE = 0x000D;
  JOY_BAUD = 0x0088;
  JOY_CTRL = 0;
}

/* TXEN, /JOYn low, ACK interrupt enable; slot 1 or 2. psx-spx asks for a short delay before the
   first byte. */
static void sio_select(int slot) {
  JOY_CTRL = slot == 2 ? 0x3003 : 0x1003;
  delay(100);
}

static void sio_deselect(void) {
  JOY_CTRL = 0;
  delay(100);
}

/* Sends one byte and returns the byte received; *ack = 1 if /ACK (IRQ7) followed it. */
static uint8_t sio_xfer(uint8_t b, int *ack) {
  JOY_CTRL = JOY_CTRL | 0x10; /* acknowledge JOY_STAT.9 */
  I_STAT = ~IRQ_PAD;          /* acknowledge I_STAT.7 (write 0) */
  JOY_DATA = b;
  int i;
  for (i = 0; i < RX_TIMEOUT && !(JOY_STAT & 2); ++i) {
  }
  uint8_t r = JOY_DATA;
  *ack = 0;
  for (i = 0; i < ACK_TIMEOUT; ++i)
    if (I_STAT & IRQ_PAD) {
      *ack = 1;
      break;
    }
  return r;
}

/* One whole command: select `slot`, send tx[0..n-1] into rx/acks, deselect. */
static void sio_command(int slot, const uint8_t *tx, uint8_t *rx, int *acks, int n) {
  sio_select(slot);
  for (int i = 0; i < n; ++i) rx[i] = sio_xfer(tx[i], &acks[i]);
  sio_deselect();
}

/* Runs a command and checks every reply byte against `expected`, and /ACK after all bytes but
   the last. */
static void expect_command(const char *name, int slot, const uint8_t *tx, const uint8_t *expected, int n) {
  uint8_t rx[16];
  int acks[16];
  sio_command(slot, tx, rx, acks, n);
  for (int i = 0; i < n; ++i) {
    if (rx[i] != expected[i] || acks[i] != (i < n - 1)) {
      tty_printf("  %s byte %d: sent %02x\n", name, i, tx[i]);
    }
    CHECK_EQ(name, rx[i], expected[i]);
    CHECK_EQ(name, acks[i], i < n - 1);
  }
}

#endif
