/* Memory card protocol through the SIO0 registers, no BIOS (psx-spx "Memory Card Read/Write
   Commands"): get ID, FLAG byte, a write/read round trip with checksums, a refused bad checksum
   and a refused bad sector. Needs a card in slot 1 (psxrl run --memcard1 FILE); the card may
   hold data from earlier runs, so the written pattern is derived from what is read first. */
#include "sio_port.h"

#define SECTOR 0x01A5

/* Reads `sector`: returns the end byte; data, checksum, FLAG and /ACK flags go out. */
static uint8_t card_read(uint16_t sector, uint8_t *data, uint8_t *flag, uint8_t *chk, int *all_acked) {
  uint8_t head[10] = {0x81, 0x52, 0x00, 0x00, (uint8_t)(sector >> 8), (uint8_t)sector, 0, 0, 0, 0};
  static const uint8_t expect_head[8] = {0xFF, 0x00, 0x5A, 0x5D, 0x00, 0x00, 0x5C, 0x5D};
  uint8_t rx[10];
  int ack, acks = 1;
  *all_acked = 0;
  sio_select(1);
  for (int i = 0; i < 10; ++i) {
    rx[i] = sio_xfer(head[i], &ack);
    if (!ack) { /* no card (or it refused): stop here instead of timing out on every byte */
      sio_deselect();
      CHECK_EQ("read: /ACK on header byte", i, 10);
      return 0;
    }
  }
  *flag = rx[1];
  for (int i = 2; i < 8; ++i) CHECK_EQ("read header", rx[i], i == 5 ? (uint8_t)(sector >> 8) : expect_head[i]);
  CHECK_EQ("read confirmed MSB", rx[8], (uint8_t)(sector >> 8));
  CHECK_EQ("read confirmed LSB", rx[9], (uint8_t)sector);
  for (int i = 0; i < 128; ++i) {
    data[i] = sio_xfer(0x00, &ack);
    acks &= ack;
  }
  *chk = sio_xfer(0x00, &ack);
  acks &= ack;
  uint8_t end = sio_xfer(0x00, &ack);
  CHECK_EQ("read end byte: no /ACK", ack, 0);
  sio_deselect();
  *all_acked = acks;
  return end;
}

/* Writes `sector` with checksum `chk`; returns the end byte and checks the "previous byte"
   replies. */
static uint8_t card_write(uint16_t sector, const uint8_t *data, uint8_t chk) {
  uint8_t head[6] = {0x81, 0x57, 0x00, 0x00, (uint8_t)(sector >> 8), (uint8_t)sector};
  int ack;
  uint8_t prev = head[5];
  sio_select(1);
  for (int i = 0; i < 6; ++i) {
    sio_xfer(head[i], &ack);
    if (!ack) {
      sio_deselect();
      CHECK_EQ("write: /ACK on header byte", i, 6);
      return 0;
    }
  }
  for (int i = 0; i < 128; ++i) {
    uint8_t r = sio_xfer(data[i], &ack);
    if (r != prev) CHECK_EQ("write data reply = previous byte", r, prev);
    prev = data[i];
  }
  CHECK_EQ("write checksum reply", sio_xfer(chk, &ack), prev);
  CHECK_EQ("write ack 1", sio_xfer(0x00, &ack), 0x5C);
  CHECK_EQ("write ack 2", sio_xfer(0x00, &ack), 0x5D);
  uint8_t end = sio_xfer(0x00, &ack);
  CHECK_EQ("write end byte: no /ACK", ack, 0);
  sio_deselect();
  return end;
}

static uint8_t checksum(uint16_t sector, const uint8_t *data) {
  uint8_t c = (uint8_t)(sector >> 8) ^ (uint8_t)sector;
  for (int i = 0; i < 128; ++i) c ^= data[i];
  return c;
}

static void get_id(void) {
  static const uint8_t tx[] = {0x81, 0x53, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00};
  /* FLAG 08h: bit 3 set at power-up until the first write. */
  static const uint8_t rx[] = {0xFF, 0x08, 0x5A, 0x5D, 0x5C, 0x5D, 0x04, 0x00, 0x00, 0x80};
  expect_command("get ID", 1, tx, rx, 10);
}

static void round_trip(void) {
  uint8_t old[128], pattern[128], back[128], flag, chk;
  int acked;
  CHECK_EQ("read old: end", card_read(SECTOR, old, &flag, &chk, &acked), 0x47);
  CHECK_EQ("read old: checksum", chk, checksum(SECTOR, old));
  CHECK_EQ("read old: /ACKs", acked, 1);
  for (int i = 0; i < 128; ++i) pattern[i] = (uint8_t)(~old[i] + i * 5);

  CHECK_EQ("write: end 47h", card_write(SECTOR, pattern, checksum(SECTOR, pattern)), 0x47);
  CHECK_EQ("read back: end", card_read(SECTOR, back, &flag, &chk, &acked), 0x47);
  CHECK_EQ("FLAG after write", flag, 0x00);
  CHECK_EQ("read back: checksum", chk, checksum(SECTOR, pattern));
  int diffs = 0;
  for (int i = 0; i < 128; ++i) diffs += back[i] != pattern[i];
  CHECK_EQ("read back: data", diffs, 0);

  uint8_t other[128];
  for (int i = 0; i < 128; ++i) other[i] = (uint8_t)(pattern[i] ^ 0x5A);
  CHECK_EQ("bad checksum: end 4Eh", card_write(SECTOR, other, (uint8_t)(checksum(SECTOR, other) + 1)), 0x4E);
  card_read(SECTOR, back, &flag, &chk, &acked);
  diffs = 0;
  for (int i = 0; i < 128; ++i) diffs += back[i] != pattern[i];
  CHECK_EQ("bad checksum: data unchanged", diffs, 0);
  CHECK_EQ("bad sector: end FFh", card_write(0x0400, other, checksum(0x0400, other)), 0xFF);
}

static void bad_sector_read(void) {
  /* Sony cards confirm a sector past 3FFh as FFFFh and stop without /ACK. */
  static const uint8_t tx[] = {0x81, 0x52, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00};
  static const uint8_t rx[] = {0xFF, 0x00, 0x5A, 0x5D, 0x00, 0x04, 0x5C, 0x5D, 0xFF, 0xFF};
  expect_command("bad sector read", 1, tx, rx, 10);
}

static void header_frame(void) {
  uint8_t d[128], flag, chk;
  int acked;
  card_read(0, d, &flag, &chk, &acked);
  CHECK_EQ("header 'M'", d[0], 'M');
  CHECK_EQ("header 'C'", d[1], 'C');
  CHECK_EQ("header checksum", chk, checksum(0, d));
}

int main(void) {
  sio_init();
  get_id();
  round_trip();
  bad_sector_read();
  header_frame();
  return test_done("sio_memcard");
}
