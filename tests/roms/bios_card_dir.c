/* The memory card directory calls (psx-spx "BIOS File Functions", "BIOS Memory Card Functions",
   "Memory Card Data Format"), run with a card in slot 1 and none in slot 2: format writes block 0
   as a freshly formatted card ("MC" header with checksum 0Eh = 'M' xor 'C', 15 free directory
   frames A0h with next block FFFFh, broken sector list entries FFFFFFFFh, write test frame = the
   header); rename changes a file's name in its directory frame (errors 11h exists, 02h not
   found, 12h another device); erase, the find mode (C0h:1Ah/1Dh: 1 lists deleted files, attribute
   A0h) and undelete (A1h back to 51h); _card_chan names the slot of the last low-level access
   (00h/10h); bufs_cb_0/4 with no access under way deliver no event. */
#include "bios_calls.h"
#include "bios_file_calls.h"
#include "psx/test.h"

static uint8_t frame[128];
static uint32_t events[4]; /* HwCARD done, HwCARD timeout, SwCARD done, SwCARD error */

static void open_events(void) {
  const uint32_t cls[4] = {0xF0000011, 0xF0000011, 0xF4000001, 0xF4000001};
  const uint32_t spec[4] = {0x0004, 0x0100, 0x0004, 0x8000};
  for (int i = 0; i < 4; ++i) {
    events[i] = open_event(cls[i], spec[i], 0x2000, 0);
    enable_event(events[i]);
  }
}

/* The first of `events` that becomes ready (a BIOS completes card accesses frames later). */
static int wait_card_event(void) {
  for (uint32_t n = 0; n < 2000000; ++n)
    for (int i = 0; i < 4; ++i)
      if (test_event(events[i])) return i;
  return -1;
}

/* Reads block 0 sector n into frame; the XOR of all 128 bytes (0 for a sealed frame). */
static uint32_t read_frame(uint32_t n) {
  card_read(0x00, n, frame);
  card_wait(0);
  for (int i = 0; i < 4; ++i) test_event(events[i]);
  uint8_t x = 0;
  for (int i = 0; i < 128; ++i) x ^= frame[i];
  return x;
}

static uint32_t word(const uint8_t *p) { return p[0] | p[1] << 8 | p[2] << 16 | (uint32_t)p[3] << 24; }

static void create(const char *path) { file_close(file_open(path, O_WRITE | O_CREAT | O_BLOCKS(1))); }

static void format(void) {
  struct dir_entry e;
  create("bu00:OLDFILE");
  CHECK_EQ("format", file_format("bu00:"), 1);
  uint32_t x = read_frame(0);
  CHECK_EQ("header: \"MC\"", frame[0] == 'M' && frame[1] == 'C', 1);
  CHECK_EQ("header: checksum 0Eh", frame[127], 0x0E);
  CHECK_EQ("header: sealed", x, 0);
  uint8_t header[128];
  for (int i = 0; i < 128; ++i) header[i] = frame[i];
  int free_frames = 0;
  for (uint32_t n = 1; n <= 15; ++n) {
    x = read_frame(n);
    free_frames += x == 0 && word(frame) == 0xA0 && word(frame + 4) == 0 && (frame[8] | frame[9] << 8) == 0xFFFF;
  }
  CHECK_EQ("15 free directory frames", free_frames, 15);
  read_frame(16);
  CHECK_EQ("broken sector list: none", word(frame), 0xFFFFFFFF);
  read_frame(63);
  CHECK_EQ("write test frame = header", bios_memcmp(frame, header, 128), 0);
  CHECK_EQ("no files after format", (uint32_t)first_file("bu00:*", &e), 0);
  CHECK_EQ("format of an unknown device", file_format("xyz:"), 0);
  CHECK_EQ("_get_errno: unknown device", get_errno(), 0x13);
}

static void rename_files(void) {
  struct dir_entry e;
  create("bu00:DIRTEST1");
  create("bu00:DIRTEST3");
  CHECK_EQ("rename", file_rename("bu00:DIRTEST1", "bu00:DIRTEST2"), 1);
  CHECK_EQ("the new name is listed", (uint32_t)first_file("bu00:DIRTEST2", &e), (uint32_t)&e);
  CHECK_EQ("direntry name", bios_strcmp(e.name, "DIRTEST2"), 0);
  CHECK_EQ("the old name is gone", file_open("bu00:DIRTEST1", O_READ), -1);
  CHECK_EQ("rename onto an existing name", file_rename("bu00:DIRTEST2", "bu00:DIRTEST3"), 0);
  CHECK_EQ("_get_errno: exists", get_errno(), 0x11);
  CHECK_EQ("rename of a missing file", file_rename("bu00:NOSUCHFILE", "bu00:OTHER"), 0);
  CHECK_EQ("_get_errno: not found", get_errno(), 0x02);
  CHECK_EQ("rename to the other slot", file_rename("bu00:DIRTEST2", "bu10:DIRTEST2"), 0);
  CHECK_EQ("_get_errno: another device", get_errno(), 0x12);
  uint32_t x = read_frame(e.sector / 64);
  CHECK_EQ("frame: new name", bios_strcmp((char *)frame + 10, "DIRTEST2"), 0);
  CHECK_EQ("frame: sealed", x, 0);
}

static void undelete(void) {
  struct dir_entry e;
  CHECK_EQ("erase", file_erase("bu00:DIRTEST2"), 1);
  CHECK_EQ("find mode at start: normal", get_card_find_mode(), 0);
  set_card_find_mode(1);
  CHECK_EQ("find mode 1", get_card_find_mode(), 1);
  CHECK_EQ("mode 1 lists the deleted file", (uint32_t)first_file("bu00:DIRTEST*", &e), (uint32_t)&e);
  CHECK_EQ("deleted direntry name", bios_strcmp(e.name, "DIRTEST2"), 0);
  CHECK_EQ("deleted direntry attribute A0h", e.attr, 0xA0);
  CHECK_EQ("mode 1 skips files in use", (uint32_t)next_file(&e), 0);
  set_card_find_mode(0);
  CHECK_EQ("mode 0 skips the deleted file", (uint32_t)first_file("bu00:DIRTEST2", &e), 0);
  CHECK_EQ("undelete", file_undelete("bu00:DIRTEST2"), 1);
  CHECK_EQ("listed again", (uint32_t)first_file("bu00:DIRTEST2", &e), (uint32_t)&e);
  CHECK_EQ("attribute 50h", e.attr, 0x50);
  read_frame(e.sector / 64);
  CHECK_EQ("frame: state 51h again", word(frame), 0x51);
  CHECK_EQ("undelete of a file in use", file_undelete("bu00:DIRTEST2"), 0);
  CHECK_EQ("_get_errno: not found", get_errno(), 0x02);
}

static void low_level(void) {
  card_read(0x00, 0, frame);
  CHECK_EQ("_card_read slot 1: done", wait_card_event(), 0);
  CHECK_EQ("_card_chan: slot 1", card_chan(), 0x00);
  card_info(0x10);
  CHECK_EQ("_card_info slot 2 (empty): timeout", wait_card_event(), 1);
  CHECK_EQ("_card_chan: slot 2", card_chan(), 0x10);
  bufs_cb_0();
  bufs_cb_4();
  int pending = 0;
  for (int i = 0; i < 4; ++i) pending += test_event(events[i]);
  CHECK_EQ("bufs_cb_0/4 with nothing under way: no event", pending, 0);
}

int main(void) {
  open_events();
  init_card(0);
  start_card();
  bu_init();
  format();
  rename_files();
  undelete();
  low_level();
  stop_card();
  return test_done("bios_card_dir");
}
