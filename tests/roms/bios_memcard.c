/* The kernel's memory card functions (psx-spx "BIOS Memory Card Functions", "Memory Card Data
   Format", "Event Summary"), run with a card in slot 1 and none in slot 2. A file is created on
   "bu00:" with one block (access mode bit 9, bits 16-31 = blocks: size 2000h), written and read
   back in 80h-byte sectors, listed by firstfile2, read and written through _card_read/_card_write
   at the sector firstfile2 reports, its directory frame checked (state 51h, size, name, XOR
   checksum over bytes 00h-7Eh in byte 7Fh), and erased (state A1h: deleted first block). The card
   file may hold the file from an earlier run: it is erased first, unchecked. */
#include "bios_calls.h"
#include "bios_file_calls.h"
#include "psx/test.h"

#define NAME "bu00:PSXRLTEST"
static uint8_t data[256], back[256], frame[128];

static int differ(const uint8_t *a, const uint8_t *b, uint32_t n) {
  int bad = 0;
  for (uint32_t i = 0; i < n; ++i) bad += a[i] != b[i];
  return bad;
}

static uint32_t events[4];  /* HwCARD done, HwCARD timeout, SwCARD done, SwCARD new card */

static void open_events(void) {
  const uint32_t cls[4] = {0xF0000011, 0xF0000011, 0xF4000001, 0xF4000001};
  const uint32_t spec[4] = {0x0004, 0x0100, 0x0004, 0x2000};
  for (int i = 0; i < 4; ++i) {
    events[i] = open_event(cls[i], spec[i], 0x2000, 0);
    enable_event(events[i]);
  }
}

/* A BIOS completes a card access on interrupt level, frames later: the first of `events` that
   becomes ready (its index), or -1 after a bounded wait. */
static int wait_card_event(void) {
  for (uint32_t n = 0; n < 2000000; ++n)
    for (int i = 0; i < 4; ++i)
      if (test_event(events[i])) return i;
  return -1;
}

/* Whether events[i] becomes ready within a bounded wait. */
static int wait_one(int i) {
  for (uint32_t n = 0; n < 2000000; ++n)
    if (test_event(events[i])) return 1;
  return 0;
}

static void low_level(void) {
  CHECK_EQ("InitCARD2 the first time", init_card(1), 0);
  CHECK_EQ("StartCARD2", start_card(), 1);
  CHECK_EQ("_card_status after start: ready", card_status(0), 0x01);
  CHECK_EQ("_card_info(slot 1) is issued", card_info(0x00), 1);
  /* FLAG bit 3 is set from power-up until the card's first write: a "new card". */
  CHECK_EQ("_card_info on a card not written since power-up: new card", wait_card_event(), 3);
  CHECK_EQ("_card_info(slot 2) is issued", card_info(0x10), 1);
  CHECK_EQ("no card in slot 2: HwCARD timeout", wait_card_event(), 1);
  CHECK_EQ("_card_status(slot 2): failed/timeout", card_status(1), 0x11);
  /* After the new-card check: a BIOS's _bu_init may read both cards' directories at once (OpenBIOS
     does, and its write test clears the new-card flag; its probe of the empty slot 2 delivers a
     timeout event), so its events are consumed before the next waits. */
  CHECK_EQ("_bu_init", bu_init(), 0);
  for (int i = 0; i < 4; ++i) test_event(events[i]);
  CHECK_EQ("card_write_test", card_write_test(0x00), 1);
  CHECK_EQ("card_write_test: HwCARD done", wait_card_event(), 0);
  CHECK_EQ("_card_load", card_load(0x00), 1);
  /* _card_load reads the directory: a BIOS may deliver HwCARD done per sector before SwCARD
     done, so SwCARD's own event is awaited. */
  CHECK_EQ("_card_load: SwCARD done, no longer a new card", wait_one(2), 1);
  for (int i = 0; i < 4; ++i) test_event(events[i]);
  new_card(); /* no result (psx-spx "_new_card") */
  CHECK_EQ("_card_auto off", card_auto(0), 0);
}

static void files(void) {
  for (int i = 0; i < 256; ++i) data[i] = (uint8_t)(i * 13 + 5);
  file_erase(NAME);
  int32_t fd = file_open(NAME, O_WRITE | O_CREAT | O_BLOCKS(1));
  CHECK_EQ("create: first free handle", fd, 2);
  CHECK_EQ("write two sectors", file_write(fd, data, 256), 256);
  CHECK_EQ("lseek to the start", file_lseek(fd, 0, 0), 0);
  CHECK_EQ("read them back", file_read(fd, back, 256), 256);
  CHECK_EQ("read-back bytes", differ(data, back, 256), 0);
  CHECK_EQ("close", file_close(fd), fd);
  CHECK_EQ("create again: exists", file_open(NAME, O_WRITE | O_CREAT | O_BLOCKS(1)), -1);
  CHECK_EQ("_get_errno: file already exists", get_errno(), 0x11);
  CHECK_EQ("open of a missing file", file_open("bu00:NOSUCHFILE", O_READ), -1);
  CHECK_EQ("_get_errno: not found", get_errno(), 0x02);
  CHECK_EQ("create with more blocks than the card has", file_open("bu00:PSXRLBIG", O_CREAT | O_BLOCKS(16)), -1);
  CHECK_EQ("_get_errno: not enough free blocks", get_errno(), 0x1C);

  fd = file_open(NAME, O_READ);
  CHECK_EQ("reopen", fd, 2);
  CHECK_EQ("lseek to the second sector", file_lseek(fd, 128, 0), 128);
  CHECK_EQ("read one sector", file_read(fd, back, 128), 128);
  CHECK_EQ("second sector's bytes", differ(data + 128, back, 128), 0);
  CHECK_EQ("lseek unaligned", file_lseek(fd, 1, 0), 1);
  CHECK_EQ("unaligned read fails", file_read(fd, back, 128), -1);
  CHECK_EQ("_get_errno: alignment", get_errno(), 0x16);
  file_lseek(fd, 0x2000, 0);
  CHECK_EQ("read past the file's end fails", file_read(fd, back, 128), -1);
  CHECK_EQ("putc on a card: not a whole sector", file_putc('x', fd), -1);
  file_close(fd);

  /* Access mode bit 15: read returns at once and completion is the SwCARD done event. */
  bios_memset(back, 0, sizeof back);
  fd = file_open(NAME, O_READ | 0x8000);
  CHECK_EQ("asynchronous read returns 0", file_read(fd, back, 128), 0);
  uint32_t done = 0;
  for (uint32_t n = 0; n < 2000000 && !done; ++n) done = test_event(events[2]);
  CHECK_EQ("asynchronous read: SwCARD done", done, 1);
  CHECK_EQ("asynchronous read's bytes", differ(data, back, 128), 0);
  file_close(fd);
}

static void listing(void) {
  struct dir_entry e;
  CHECK_EQ("firstfile2", (uint32_t)first_file("bu00:PSXRL*", &e), (uint32_t)&e);
  CHECK_EQ("direntry name", bios_strcmp(e.name, "PSXRLTEST"), 0);
  CHECK_EQ("direntry size: one block", e.size, 0x2000);
  CHECK_EQ("direntry attribute: in use", e.attr, 0x50);
  CHECK_EQ("first sector: a block start in blocks 1-15", e.sector % 64 == 0 && e.sector >= 64 && e.sector <= 960, 1);
  CHECK_EQ("nextfile: no other match", (uint32_t)next_file(&e), 0);

  CHECK_EQ("_card_read of the file's first sector", card_read(0x00, e.sector, back), 1);
  CHECK_EQ("_card_read: HwCARD done", wait_card_event(), 0);
  CHECK_EQ("raw sector = file bytes 0-127", differ(data, back, 128), 0);
  card_wait(0); /* a BIOS takes the next command once the slot is ready again */
  for (int i = 0; i < 128; ++i) back[i] = (uint8_t)~data[128 + i];
  CHECK_EQ("_card_write of its second sector", card_write(0x00, e.sector + 1, back), 1);
  CHECK_EQ("_card_wait", card_wait(0), 0x01);
  int32_t fd = file_open(NAME, O_READ);
  file_lseek(fd, 128, 0);
  file_read(fd, data, 128);
  file_close(fd);
  CHECK_EQ("the file reads what _card_write wrote", differ(data, back, 128), 0);

  uint32_t dir_sector = e.sector / 64;  /* directory frame n describes block n */
  CHECK_EQ("_card_read of the directory frame", card_read(0x00, dir_sector, frame), 1);
  card_wait(0);
  uint8_t x = 0;
  for (int i = 0; i < 128; ++i) x ^= frame[i];
  CHECK_EQ("frame: state 51h, in use, first block", frame[0], 0x51);
  CHECK_EQ("frame: size", frame[4] | frame[5] << 8 | frame[6] << 16, 0x2000);
  CHECK_EQ("frame: no next block", frame[8] | frame[9] << 8, 0xFFFF);
  CHECK_EQ("frame: name", bios_strcmp((char *)frame + 10, "PSXRLTEST"), 0);
  CHECK_EQ("frame: checksum", x, 0);

  CHECK_EQ("erase", file_erase(NAME), 1);
  CHECK_EQ("erased file is not listed", (uint32_t)first_file("bu00:PSXRL*", &e), 0);
  card_read(0x00, dir_sector, frame);
  card_wait(0);
  CHECK_EQ("frame: state A1h, deleted first block", frame[0], 0xA1);
  CHECK_EQ("erase of a missing file", file_erase(NAME), 0);
  CHECK_EQ("StopCARD2", stop_card(), 1);
}

int main(void) {
  open_events();
  low_level();
  files();
  listing();
  return test_done("bios_memcard");
}
