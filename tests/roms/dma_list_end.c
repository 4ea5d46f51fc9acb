/* DMA linked-list end markers (psx-spx "DMA Channels"; the expected values are those of
   pcsx-redux's src/mips/tests/dma, whose checks were run on a console). A next-node address with
   bit 23 set ends a GPU list; only 0x00FFFFFF ends it cleanly. Any other marker (0x800000,
   0x800001, 0xFFFFF0) also sets DICR bit 15, the bus error flag, which forces bit 31 and stays set
   until the CPU writes it 0. */
#include "dma_regs.h"
#include "gpu_rom.h"

static uint32_t node[2];

/* One node: GP0(E1h) texpage 0x555, then the end marker `marker`. Checks what the list leaves:
   GPUSTAT's texpage bits (the word reached the GPU), BCR untouched, MADR on the marker, CHCR's
   start bit clear, IRQ3 raised; returns DICR. 5 checks. */
static uint32_t run_list(uint32_t marker) {
  GPU_GP1 = 0x00000000;
  GPU_GP1 = 0x04000001;
  gp0(0xE1000000);
  DPCR = 0x00000800;
  DICR = 0x00840000; /* master enable + DMA2 enable */
  I_STAT = 0;
  node[0] = 0x01000000 | marker;
  node[1] = 0xE1000555;
  GPU_GP1 = 0x04000002; /* DMA direction CPU->GP0 */
  D_MADR(2) = PHYS(node);
  D_BCR(2) = 0x12345678;
  D_CHCR(2) = 0x01000401;
  if (!dma_wait(2)) TEST_TIMEOUT("the GPU linked list to end");
  CHECK_EQ("list reached the GPU", GPU_STAT & 0x7FF, 0x555);
  CHECK_EQ("list bcr untouched", D_BCR(2), 0x12345678);
  CHECK_EQ("list madr on the marker", D_MADR(2), marker);
  CHECK_EQ("list chcr", D_CHCR(2), 0x00000401);
  CHECK_EQ("list irq3", I_STAT & 8, 8);
  return DICR;
}

/* 0x00FFFFFF: the clean end. Acknowledging the channel's flag leaves 0x00840000. 2 + 5 checks. */
static void clean_end(void) {
  uint32_t dicr = run_list(0x00FFFFFF);
  CHECK_EQ("0xFFFFFF: dicr", dicr, 0x84840000);
  DICR = (dicr & 0x00FFFFFF) | 0x04000000;
  CHECK_EQ("0xFFFFFF: acknowledged", DICR, 0x00840000);
}

/* Any other marker: bit 15 set. Acknowledging the flag while writing bit 15 back keeps bit 31
   (0x80848000); writing bit 15 as 0 clears both. 3 + 5 checks per marker. */
static void unclean_end(uint32_t marker) {
  uint32_t dicr = run_list(marker);
  CHECK_EQ("unclean end: dicr", dicr, 0x84848000);
  DICR = (dicr & 0x00FFFFFF) | 0x04000000;
  dicr = DICR;
  CHECK_EQ("unclean end: flag acknowledged, bit 15 kept", dicr, 0x80848000);
  DICR = dicr & 0x00FF7FFF;
  CHECK_EQ("unclean end: bit 15 cleared", DICR, 0x00840000);
}

/* 0x800000 again, then DICR = 0x8000 (enables off, flag not acknowledged): 0x84008000; DICR = 0:
   0x04000000 (the flag stays, bit 31 falls with bits 15 and 23). 2 + 5 checks. */
static void unclean_end_toggle(void) {
  run_list(0x00800000);
  DICR = 0x00008000;
  CHECK_EQ("toggle: bit 15 alone", DICR, 0x84008000);
  DICR = 0;
  CHECK_EQ("toggle: all written 0", DICR, 0x04000000);
}

int main(void) {
  clean_end();
  unclean_end(0x00800000);
  unclean_end(0x00800001);
  unclean_end(0x00FFFFF0);
  unclean_end_toggle();
  DICR = 0x04000000;
  return test_done("dma_list_end");
}
