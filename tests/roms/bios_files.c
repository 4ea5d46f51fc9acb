/* The kernel's file functions on "cdrom:" and "tty:" (psx-spx "BIOS File Functions", "BIOS CDROM
   Functions"), run with cdrom.cmake's disc: DATA.BIN holds 4096 letters, byte i = 'A' + (i * 7 + 3)
   % 26. Expected results are psx-spx's: handles 0 and 1 are stdin/stdout so a first open returns 2;
   reads on cdrom: take whole 800h-byte sectors from a sector-aligned position inside the file,
   else -1 with error 16h; writing to cdrom returns 0; close returns the handle; an unknown name
   gives error 02h, an unknown device 13h, a bad handle 09h. */
#include "bios_calls.h"
#include "bios_file_calls.h"
#include "psx/test.h"

static uint8_t buf[4096] __attribute__((aligned(4)));

/* Bytes of buf[0..n) that differ from DATA.BIN's bytes from offset `from`. */
static int mismatches(uint32_t from, uint32_t n) {
  int bad = 0;
  for (uint32_t i = 0; i < n; ++i)
    if (buf[i] != (uint8_t)('A' + ((from + i) * 7 + 3) % 26)) ++bad;
  return bad;
}

static void cdrom_reads(void) {
  cd_init();
  int32_t fd = file_open("cdrom:\\DATA.BIN;1", O_READ);
  CHECK_EQ("open: first free handle after stdin/stdout", fd, 2);
  CHECK_EQ("read one sector", file_read(fd, buf, 2048), 2048);
  CHECK_EQ("sector 0 holds DATA.BIN's first bytes", mismatches(0, 2048), 0);
  CHECK_EQ("lseek from the start", file_lseek(fd, 2048, 0), 2048);
  CHECK_EQ("read the second sector", file_read(fd, buf, 2048), 2048);
  CHECK_EQ("sector 1 holds bytes 2048-4095", mismatches(2048, 2048), 0);
  CHECK_EQ("read at the file's end fails", file_read(fd, buf, 2048), -1);
  CHECK_EQ("_get_errno: fpos >= filesize", get_errno(), 0x16);
  CHECK_EQ("_get_error of the handle", get_error(fd), 0x16);
  CHECK_EQ("lseek back from the current position", file_lseek(fd, -4096, 1), 0);
  CHECK_EQ("read both sectors at once", file_read(fd, buf, 4096), 4096);
  CHECK_EQ("both sectors' bytes", mismatches(0, 4096), 0);
  CHECK_EQ("lseek to an unaligned position", file_lseek(fd, 100, 0), 100);
  CHECK_EQ("unaligned read fails", file_read(fd, buf, 2048), -1);
  file_lseek(fd, 0, 0);
  CHECK_EQ("partial-sector read fails", file_read(fd, buf, 100), -1);
  CHECK_EQ("getc reads one byte: never a whole sector", file_getc(fd), -1);
  CHECK_EQ("write to cdrom returns 0", file_write(fd, buf, 2048), 0);
  CHECK_EQ("close returns the handle", file_close(fd), fd);
  CHECK_EQ("close again fails", file_close(fd), -1);
  CHECK_EQ("_get_errno: bad handle", get_errno(), 0x09);
  CHECK_EQ("read on a closed handle fails", file_read(fd, buf, 2048), -1);
  CHECK_EQ("open of a missing file", file_open("cdrom:\\NOFILE.BIN;1", O_READ), -1);
  CHECK_EQ("_get_errno: file not found", get_errno(), 0x02);
  CHECK_EQ("open on an unknown device", file_open("floppy:DATA.BIN", O_READ), -1);
  CHECK_EQ("_get_errno: unknown device", get_errno(), 0x13);
}

/* cd, B0h's open/read/close, firstfile2/nextfile and the sector calls. */
static void cdrom_directory(void) {
  CHECK_EQ("cd to the root", file_cd("cdrom:\\"), 1);
  int32_t fd = b_open("cdrom:DATA.BIN;1", O_READ);
  CHECK_EQ("B0h open of a name relative to cd's directory", fd, 2);
  CHECK_EQ("B0h read", b_read(fd, buf, 2048), 2048);
  CHECK_EQ("B0h read's bytes", mismatches(0, 2048), 0);
  CHECK_EQ("B0h close", b_close(fd), fd);

  struct dir_entry e;
  int32_t lbn = cd_get_lbn("\\DATA.BIN;1");
  CHECK_EQ("CdGetLbn finds the file after the system area", lbn >= 16, 1);
  CHECK_EQ("firstfile2 with a '*' pattern", (uint32_t)first_file("cdrom:\\DATA*", &e), (uint32_t)&e);
  CHECK_EQ("direntry name", bios_strcmp(e.name, "DATA.BIN;1"), 0);
  CHECK_EQ("direntry size", e.size, 4096);
  CHECK_EQ("direntry attribute: always 0 for cdrom", e.attr, 0);
  CHECK_EQ("direntry first sector = CdGetLbn", e.sector, lbn);
  CHECK_EQ("nextfile: no second match", (uint32_t)next_file(&e), 0);
  CHECK_EQ("'?' matches one character", (uint32_t)first_file("cdrom:\\DAT?.BIN;1", &e), (uint32_t)&e);
  CHECK_EQ("no match", (uint32_t)first_file("cdrom:\\NONE*", &e), 0);

  bios_memset(buf, 0, sizeof buf);
  CHECK_EQ("CdReadSector returns the count", cd_read_sector(2, lbn, buf), 2);
  CHECK_EQ("CdReadSector's bytes", mismatches(0, 4096), 0);
  CHECK_EQ("CdGetStatus: shell closed", cd_get_status() & 0x10, 0);
  cd_remove();
}

/* The TTY handles: stdout takes writes, and a closed stdout is reopened as "tty:" on the lowest
   free handle, as PSn00bSDK's console example does. */
static void tty_handles(void) {
  CHECK_EQ("write to stdout", file_write(1, "tty ok\n", 7), 7);
  CHECK_EQ("putc to stdout writes one byte", file_putc('\n', 1), 1);
  CHECK_EQ("close stdin", file_close(0), 0);
  CHECK_EQ("write to the closed stdin", file_write(0, "x", 1), -1);
  CHECK_EQ("reopen tty: on handle 0", file_open("tty:", O_READ | O_WRITE), 0);
  CHECK_EQ("getchar returns a 7-bit character without TTY input", tty_getchar() & ~0x7F, 0);
}

int main(void) {
  cdrom_reads();
  cdrom_directory();
  tty_handles();
  return test_done("bios_files");
}
