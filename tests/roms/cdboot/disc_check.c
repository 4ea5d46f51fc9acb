/* Booted by the cdboot boot ROM from a disc made by mkdisc (tests/roms/cdrom_cdboot.cmake):
   checks what the ROM leaves it, as a BIOS would: the stack at SYSTEM.CNF's STACK (801FFE00), its
   initialised data in place, the drive idle with its motor on (Getstat = 0x02, psx-spx "CDROM Status Byte"), and
   that its own data file is still readable through the drive: DATA.BIN holds 4096 bytes,
   byte i = 'A' + (i * 7 + 3) % 26. */
#include <stdint.h>

#include "cd.h"
#include "psx/test.h"

#define DATA_SIZE 4096

static uint8_t data[DATA_SIZE];
/* Initialised data travels inside the EXE's text; a wrongly loaded text would change it. */
static volatile uint32_t marker = 0x5AA5C33Cu;

int main(void) {
  uint32_t sp;
  __asm__ volatile("move %0, $sp" : "=r"(sp));
  tty_printf("booted by the cdboot ROM\n");
  CHECK_EQ("stack just below SYSTEM.CNF STACK", sp <= 0x801FFE00u && sp > 0x801FF000u, 1);
  CHECK_EQ(".data loaded from the disc", marker, 0x5AA5C33Cu);

  CHECK_EQ("Getstat", cd_command(0x01, 0, 0, 0), CD_OK);
  CHECK_EQ("drive idle, motor on", cd_response[0], 0x02);

  uint32_t lba = 0, size = 0;
  CHECK_EQ("find DATA.BIN", iso_find("DATA.BIN", &lba, &size), CD_OK);
  CHECK_EQ("DATA.BIN size", size, DATA_SIZE);
  CHECK_EQ("read DATA.BIN", cd_read(lba, data, DATA_SIZE), CD_OK);
  int bad = 0;
  for (int i = 0; i < DATA_SIZE; ++i)
    if (data[i] != (uint8_t)('A' + (i * 7 + 3) % 26)) ++bad;
  CHECK_EQ("DATA.BIN bytes wrong", bad, 0);
  CHECK_EQ("missing file", iso_find("NOFILE.BIN", &lba, &size), CD_NOT_FOUND);
  return test_done("cdboot_disc_check");
}
