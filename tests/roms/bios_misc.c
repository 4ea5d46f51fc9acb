/* The asynchronous CD calls and the remaining small kernel calls (psx-spx "BIOS CDROM Functions",
   "BIOS Internal Boot Functions", "A(9Fh) SetMem", "gets", "returns 0" entries), run with
   cdrom.cmake's disc: DATA.BIN holds byte i = 'A' + (i * 7 + 3) % 26 over two sectors.
   CdAsyncSeekL takes MM:SS:FF in BCD for logical block + 150; CdAsyncReadSector delivers 800h bytes
   of user data, or with Setmode bit 5 924h bytes from the sector's header (MM, SS, FF, mode 2 on a
   MODE2/2352 track, subheader, then the data at 0Ch); completion is event F0000003h/20h.
   CdAsyncGetStatus gives the drive's stat byte (bit 1 motor on, bit 4 shell open). */
#include "bios_calls.h"
#include "bios_exec_calls.h"
#include "bios_file_calls.h"
#include "psx/test.h"

#define RAM_SIZE (*(volatile uint32_t *)0x1F801060)
#define RAM_MB (*(volatile uint32_t *)0x80000060)

static uint8_t buf[0x930];
static uint8_t kernel_area[0x400] __attribute__((aligned(16)));
static uint32_t cd_event;

static int wait_cd(void) {
  for (uint32_t n = 0; n < 2000000; ++n)
    if (test_event(cd_event)) return 1;
  return 0;
}

/* Bytes of p that differ from DATA.BIN's bytes from offset `from`. */
static int not_letters(const uint8_t *p, uint32_t from, uint32_t n) {
  int bad = 0;
  for (uint32_t k = 0; k < n; ++k) bad += p[k] != 'A' + ((from + k) * 7 + 3) % 26;
  return bad;
}

static uint8_t bcd(uint32_t v) { return (uint8_t)((v / 10) << 4 | v % 10); }

static void async_cd(void) {
  cd_event = open_event(0xF0000003, 0x20, 0x2000, 0);
  enable_event(cd_event);
  int32_t lba = cd_get_lbn("cdrom:\\DATA.BIN;1");
  CHECK_EQ("DATA.BIN after the system area", lba >= 16, 1);
  uint32_t at = (uint32_t)lba + 150;
  const uint8_t msf[3] = {bcd(at / 75 / 60), bcd(at / 75 % 60), bcd(at % 75)};
  CHECK_EQ("CdAsyncSeekL", cd_async_seekl(msf), 1);
  CHECK_EQ("CdAsyncSeekL: complete", wait_cd(), 1);
  CHECK_EQ("CdAsyncReadSector, 800h bytes", cd_async_read_sector(1, buf, 0x80), 1);
  CHECK_EQ("CdAsyncReadSector: complete", wait_cd(), 1);
  CHECK_EQ("first sector's data", not_letters(buf, 0, 0x800), 0);
  cd_async_read_sector(1, buf, 0x80);
  wait_cd();
  CHECK_EQ("the next read goes on with the next sector", not_letters(buf, 0x800, 0x800), 0);
  cd_async_seekl(msf);
  wait_cd();
  CHECK_EQ("CdAsyncReadSector, 924h bytes", cd_async_read_sector(1, buf, 0xA0), 1);
  wait_cd();
  CHECK_EQ("924h: the header's MM:SS:FF", buf[0] == msf[0] && buf[1] == msf[1] && buf[2] == msf[2], 1);
  CHECK_EQ("924h: the header's mode", buf[3], 2);
  CHECK_EQ("924h: the data after the subheader", not_letters(buf + 12, 0, 0x800), 0);
  uint8_t stat = 0xFF;
  CHECK_EQ("CdAsyncGetStatus", cd_async_get_status(&stat), 1);
  CHECK_EQ("CdAsyncGetStatus: complete", wait_cd(), 1);
  CHECK_EQ("stat: motor on, shell closed", stat & 0x12, 0x02);
  CHECK_EQ("CdAsyncSetMode", cd_async_set_mode(0x80), 1);
  CHECK_EQ("CdAsyncSetMode: complete", wait_cd(), 1);
}

static void small_calls(void) {
  char line[128];
  line[0] = 'x';
  CHECK_EQ("gets returns dst", (uint32_t)tty_gets(line), (uint32_t)line);
  CHECK_EQ("gets without TTY input: an empty line", line[0], 0);
  CHECK_EQ("B(3Eh) gets", (uint32_t)b_gets(line), (uint32_t)line);
  CHECK_EQ("A(57h) returns 0", a0_return_zero_57(5), 0);
  CHECK_EQ("C(0Eh) returns 0", c0_return_zero_0e(5), 0);
  print_devices();

  CHECK_EQ("RAM size word after boot: 2 MB", RAM_MB, 2);
  const uint32_t ram_size = RAM_SIZE;
  set_mem(8);
  CHECK_EQ("SetMem(8): [60h]", RAM_MB, 8);
  CHECK_EQ("SetMem(8): RAM_SIZE bits 9-11 = 5 (8 MB)", (RAM_SIZE >> 9) & 7, 5);
  set_mem(2);
  CHECK_EQ("SetMem(2): [60h]", RAM_MB, 2);
  CHECK_EQ("SetMem(2): RAM_SIZE bits 9-11 = 4 (2 MB, 6 MB locked)", (RAM_SIZE >> 9) & 7, 4);
  RAM_SIZE = ram_size;

  volatile uint32_t *vector = (volatile uint32_t *)0x80000080;
  uint32_t saved[3];
  enter_critical_section();
  for (int i = 0; i < 3; ++i) saved[i] = vector[i], vector[i] = 0;
  install_exception_handlers();
  int same = 0;
  for (int i = 0; i < 3; ++i) same += vector[i] == saved[i];
  exit_critical_section();
  CHECK_EQ("InstallExceptionHandlers: the kernel's vector at 80h again", same, 3);

  sys_init_memory(kernel_area, sizeof kernel_area);
  uint8_t *p = alloc_kernel_memory(0x40);
  CHECK_EQ("SysInitMemory: kernel memory comes from the new area",
           p >= kernel_area && p + 0x40 <= kernel_area + sizeof kernel_area, 1);
}

int main(void) {
  async_cd();
  small_calls();
  return test_done("bios_misc");
}
