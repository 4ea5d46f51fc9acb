/* Drives the CD-ROM controller directly by polling its registers (psx-spx "CDROM Controller I/O
   Ports"): Getstat, GetID and ReadTOC answers and their interrupt order, Setloc + ReadN of the
   ISO 9660 descriptors and of a data file with known contents at single and double speed, and the
   same data taken from the data FIFO by DMA channel 3 (psx-spx "DMA Channels": CDROM, sync mode 0).
   The disc is built by mkdisc (tests/roms/cdrom.cmake): DATA.BIN is the first file, at logical
   block 21 (20 = root directory), holding the letters 'A' + (i * 7 + 3) % 26. */
#include <stdint.h>

#include "dma_regs.h"
#include "psx/test.h"

#define CD_INDEX (*(volatile uint8_t *)0xBF801800)
#define CD_REG1 (*(volatile uint8_t *)0xBF801801)
#define CD_REG2 (*(volatile uint8_t *)0xBF801802)
#define CD_REG3 (*(volatile uint8_t *)0xBF801803)

static uint8_t resp[16];
static int resp_len;

static void send(uint8_t cmd, const uint8_t *params, int n) {
  CD_INDEX = 0;
  for (int i = 0; i < n; ++i) CD_REG2 = params[i];
  CD_REG1 = cmd;
}

/* Waits for the next interrupt, reads its response, acknowledges it; returns INT1..INT5 (0 on
   a time-out, which also counts as a failure). */
static int wait_int(void) {
  CD_INDEX = 1;
  for (uint32_t spin = 0; (CD_REG3 & 7) == 0; ++spin)
    if (spin > 20000000) {
      TEST_TIMEOUT("a CD-ROM interrupt (HINTSTS bits 0-2)");
      return 0;
    }
  int type = CD_REG3 & 7;
  resp_len = 0;
  while ((CD_INDEX & 0x20) && resp_len < 16) resp[resp_len++] = CD_REG1;
  CD_INDEX = 1;
  CD_REG3 = 0x1F;
  I_STAT = ~(1u << 2);
  return type;
}

/* Waits for the next interrupt other than INT1 (data ready). A drive that keeps reading sends
   INT1 at 75 sectors per second for ever; 1000 of them (13 s) means the awaited one never came. */
static int wait_int_skipping_data(void) {
  int t, sectors = 0;
  while ((t = wait_int()) == 1 && ++sectors < 1000) {
  }
  if (t == 1) TEST_TIMEOUT("a CD-ROM interrupt other than INT1 (data ready)");
  return t;
}

static void read_sector(uint8_t *buf, int n) {
  CD_INDEX = 0;
  CD_REG3 = 0x80; /* BFRD: move the sector into the data FIFO */
  for (int i = 0; i < n; ++i) buf[i] = CD_REG2;
  CD_REG3 = 0x00;
}

static uint8_t sector[2048];
static uint32_t dma_buf[512];

static int letters_wrong(const uint8_t *p, int from, int n) {
  int bad = 0;
  for (int i = 0; i < n; ++i)
    if (p[i] != (uint8_t)('A' + ((from + i) * 7 + 3) % 26)) ++bad;
  return bad;
}

/* DMA3 to RAM, sync mode 0 (CHCR bit 28 starts it at once), `words` words into dst. */
static void dma3_read(uint32_t *dst, uint32_t words) {
  D_MADR(3) = PHYS(dst);
  D_BCR(3) = words;
  D_CHCR(3) = 0x11000000;
}

/* DATA.BIN's two sectors through DMA3: the first in one 512-word transfer, the second in two
   256-word transfers that continue in the same FIFO. */
static void test_dma3(void) {
  DPCR |= 0x00008000; /* channel 3 enable */
  static const uint8_t data_loc[3] = {0x00, 0x02, 0x21};
  send(0x02, data_loc, 3);
  wait_int();
  send(0x06, 0, 0);
  CHECK_EQ("DMA ReadN INT", wait_int(), 3);
  CHECK_EQ("DMA sector 0 INT", wait_int(), 1);
  CD_INDEX = 0;
  CD_REG3 = 0x80;
  CHECK_EQ("data FIFO full (DRQSTS)", CD_INDEX & 0x40, 0x40);
  dma3_read(dma_buf, 512);
  CHECK_EQ("DMA sector 0 done", dma_wait(3), 1);
  CHECK_EQ("CHCR after", D_CHCR(3), 0x00000000);
  CHECK_EQ("data FIFO empty after 512 words", CD_INDEX & 0x40, 0);
  CHECK_EQ("DMA sector 0 bytes wrong", letters_wrong((const uint8_t *)dma_buf, 0, 2048), 0);

  CHECK_EQ("DMA sector 1 INT", wait_int(), 1);
  CD_INDEX = 0;
  CD_REG3 = 0x80;
  dma3_read(dma_buf, 256);
  CHECK_EQ("DMA first half done", dma_wait(3), 1);
  CHECK_EQ("data FIFO half full", CD_INDEX & 0x40, 0x40);
  dma3_read(dma_buf + 256, 256);
  CHECK_EQ("DMA second half done", dma_wait(3), 1);
  CHECK_EQ("DMA sector 1 bytes wrong", letters_wrong((const uint8_t *)dma_buf, 2048, 2048), 0);
  CD_REG3 = 0x00;
  send(0x09, 0, 0);
  wait_int_skipping_data();
  wait_int();
}

int main(void) {
  send(0x01, 0, 0);
  CHECK_EQ("Getstat INT", wait_int(), 3);
  CHECK_EQ("Getstat stat (motor on)", resp[0], 0x02);

  send(0x1A, 0, 0);
  CHECK_EQ("GetID first INT", wait_int(), 3);
  CHECK_EQ("GetID second INT", wait_int(), 2);
  CHECK_EQ("GetID length", resp_len, 8);
  CHECK_EQ("GetID flags", resp[1], 0x00);
  CHECK_EQ("GetID disc type", resp[2], 0x20);
  CHECK_EQ("GetID S", resp[4], 'S');
  CHECK_EQ("GetID C", resp[5], 'C');
  CHECK_EQ("GetID E", resp[6], 'E');

  send(0x1E, 0, 0);
  CHECK_EQ("ReadTOC first INT", wait_int(), 3);
  CHECK_EQ("ReadTOC second INT", wait_int(), 2);

  send(0x13, 0, 0);
  CHECK_EQ("GetTN INT", wait_int(), 3);
  CHECK_EQ("GetTN first", resp[1], 0x01);
  CHECK_EQ("GetTN last", resp[2], 0x01);

  /* Logical block 16 = 00:02:16: the primary volume descriptor, then the terminator. */
  static const uint8_t pvd_loc[3] = {0x00, 0x02, 0x16};
  send(0x02, pvd_loc, 3);
  CHECK_EQ("Setloc INT", wait_int(), 3);
  send(0x06, 0, 0);
  CHECK_EQ("ReadN first INT", wait_int(), 3);
  CHECK_EQ("ReadN sector INT", wait_int(), 1);
  CHECK_EQ("ReadN stat reading", resp[0], 0x22);
  read_sector(sector, 2048);
  CHECK_EQ("PVD type", sector[0], 1);
  CHECK_EQ("PVD id C", sector[1], 'C');
  CHECK_EQ("PVD id 1", sector[5], '1');
  CHECK_EQ("next sector INT", wait_int(), 1);
  read_sector(sector, 2048);
  CHECK_EQ("terminator type", sector[0], 0xFF);
  send(0x09, 0, 0);
  CHECK_EQ("Pause first INT", wait_int_skipping_data(), 3);
  CHECK_EQ("Pause second INT", wait_int(), 2);
  CHECK_EQ("Pause stat idle", resp[0], 0x02);

  /* DATA.BIN at logical block 21 = 00:02:21, read at double speed. */
  static const uint8_t mode[1] = {0x80};
  send(0x0E, mode, 1);
  CHECK_EQ("Setmode INT", wait_int(), 3);
  static const uint8_t data_loc[3] = {0x00, 0x02, 0x21};
  send(0x02, data_loc, 3);
  wait_int();
  send(0x06, 0, 0);
  CHECK_EQ("ReadN (data) INT", wait_int(), 3);
  int bad = 0;
  for (int s = 0; s < 2; ++s) {
    CHECK_EQ("data sector INT", wait_int(), 1);
    read_sector(sector, 2048);
    bad += letters_wrong(sector, s * 2048, 2048);
  }
  CHECK_EQ("DATA.BIN bytes wrong", bad, 0);
  send(0x09, 0, 0);
  wait_int_skipping_data();
  wait_int();

  test_dma3();

  /* An unknown command: INT5 with stat | error and 0x40. */
  send(0x1F, 0, 0);
  CHECK_EQ("bad command INT", wait_int(), 5);
  CHECK_EQ("bad command error", resp[1], 0x40);
  return test_done("cdrom_controller");
}
