/* DMA test program: OTC reverse clear, DICR flag/acknowledge/force rules, sync mode 0 with
   chopping, sync mode 1 blocks and sync mode 2 linked lists (into the MDEC, the one device whose
   word count can be read back), and the time the CPU is held (psx-spx "DMA Channels"). */
#include "dma_regs.h"
#include "psx/test.h"

static uint32_t ot[16];
static uint32_t big_ot[1024];
static uint32_t buf[16];
static uint32_t params[32];
static uint32_t list[32];

static void test_otc(void) {
  DPCR |= 0x08000000;
  DICR = 0x00C00000; /* master enable + DMA6 enable */
  I_STAT = 0;
  D_MADR(6) = PHYS(&ot[15]);
  D_BCR(6) = 16;
  D_CHCR(6) = 0x11000002;
  CHECK_EQ("otc done", dma_wait(6), 1);
  for (int i = 15; i > 0; --i) CHECK_EQ("otc entry", ot[i], PHYS(&ot[i - 1]));
  CHECK_EQ("otc end", ot[0], 0x00FFFFFF);
  CHECK_EQ("otc chcr after", D_CHCR(6), 0x00000002);
  CHECK_EQ("otc madr kept", D_MADR(6), PHYS(&ot[15]));
  CHECK_EQ("otc dicr", DICR, 0xC0C00000);
  CHECK_EQ("otc irq3", I_STAT & 8, 8);
  DICR = 0x00C00000; /* writing 0 keeps the flag */
  CHECK_EQ("dicr keep", DICR, 0xC0C00000);
  DICR = 0x40C00000; /* writing 1 acknowledges */
  CHECK_EQ("dicr ack", DICR, 0x00C00000);
}

/* Without Start/Trigger (bit 28) the OTC never starts: on the console the word stays as written
   (ps1-tests dma/otc-test, testOtcWontStartOnAutomaticMode). The CPU then stops the channel. */
static void test_otc_needs_trigger(void) {
  static volatile uint32_t word;
  word = 0x11111111;
  D_MADR(6) = PHYS(&word);
  D_BCR(6) = 1;
  D_CHCR(6) = 0x01000002;
  for (int i = 0; i < 1000; ++i) (void)D_CHCR(6);
  CHECK_EQ("otc without trigger", word, 0x11111111);
  D_CHCR(6) = 0;
}

static void test_dicr_rules(void) {
  DICR = 0x00800000; /* master on, DMA6 not enabled: no flag */
  I_STAT = 0;
  D_BCR(6) = 1;
  D_CHCR(6) = 0x11000002;
  if (!dma_wait(6)) TEST_TIMEOUT("DMA6 (OTC) to finish");
  CHECK_EQ("no flag when disabled", DICR, 0x00800000);
  CHECK_EQ("no irq when disabled", I_STAT & 8, 0);
  DICR = 0x00008000; /* force IRQ */
  CHECK_EQ("force sets bit31", DICR, 0x80008000);
  CHECK_EQ("force irq3", I_STAT & 8, 8);
  I_STAT = 0;
  DICR = 0x00008000;
  CHECK_EQ("no second edge", I_STAT & 8, 0);
  DICR = 0x0000FFFF;
  CHECK_EQ("dicr rw bits", DICR, 0x8000803F);
  DICR = 0;
}

static void test_otc_time(void) {
  /* 1024 words at 0x110 clocks per 0x100 words: the CPU is held 1088 clocks. */
  T_MODE(2) = 0;
  D_MADR(6) = PHYS(&big_ot[1023]);
  D_BCR(6) = 1024;
  uint32_t t0 = T_COUNT(2);
  D_CHCR(6) = 0x11000002;
  uint32_t t1 = T_COUNT(2);
  uint32_t held = (t1 - t0) & 0xFFFF;
  CHECK_EQ("otc held >= 1088", held >= 1088, 1);
  CHECK_EQ("otc held < 1088+64", held < 1088 + 64, 1);
  CHECK_EQ("big otc last", big_ot[0], 0x00FFFFFF);
  CHECK_EQ("big otc first", big_ot[1023], PHYS(&big_ot[1022]));
}

static void test_chopping(void) {
  /* CD-ROM channel, to RAM, chopping: 4-word DMA windows, 32-clock CPU windows. MADR advances
     and BC counts down to zero (psx-spx). */
  DPCR |= 0x00008000;
  DICR = 0x00880000;
  D_MADR(3) = PHYS(buf);
  D_BCR(3) = 10;
  D_CHCR(3) = 0x11520100;
  CHECK_EQ("chop done", dma_wait(3), 1);
  CHECK_EQ("chop madr", D_MADR(3), PHYS(buf) + 40);
  CHECK_EQ("chop bc", D_BCR(3) & 0xFFFF, 0);
  CHECK_EQ("chop dicr", DICR, 0x88880000);
  DICR = 0x08000000;
}

static void mdec_idle_check(const char *what) {
  /* Idle, output empty, no parameters pending: every word was taken, none extra. */
  CHECK_EQ(what, MDEC1 & 0xE000FFFF, 0x8000FFFF);
}

static void test_block_mode(void) {
  /* MDEC(3) needs exactly 32 parameter words: 8 blocks of 4. */
  DPCR |= 0x00000008;
  DICR = 0x00810000;
  MDEC1 = 0x80000000;
  MDEC1 = 0x60000000;
  for (int i = 0; i < 32; ++i) params[i] = 0x5A825A82;
  MDEC0 = 0x60000000;
  CHECK_EQ("mdec wants 32", MDEC1 & 0xFFFF, 31);
  D_MADR(0) = PHYS(params);
  D_BCR(0) = 0x00080004;
  D_CHCR(0) = 0x01000201;
  CHECK_EQ("block done", dma_wait(0), 1);
  CHECK_EQ("block madr end", D_MADR(0), PHYS(params) + 128);
  CHECK_EQ("block ba zero", D_BCR(0), 0x00000004);
  CHECK_EQ("block dicr", DICR, 0x81810000);
  mdec_idle_check("block words exact");
  DICR = 0x01000000;
}

static void test_linked_list(void) {
  /* MDEC(2) luminance: 16 words, delivered by a 3-node list (5 words, 0 words, 11 words). */
  DICR = 0x00810000;
  MDEC0 = 0x40000000;
  uint32_t *a = &list[0], *b = &list[8], *c = &list[12];
  a[0] = (5u << 24) | PHYS(b);
  for (int i = 1; i <= 5; ++i) a[i] = 0x01010101 * i;
  b[0] = (0u << 24) | PHYS(c);
  c[0] = (11u << 24) | 0x00FFFFFF;
  for (int i = 1; i <= 11; ++i) c[i] = 0x02020202 * i;
  D_MADR(0) = PHYS(a);
  D_BCR(0) = 0;
  D_CHCR(0) = 0x01000401;
  CHECK_EQ("list done", dma_wait(0), 1);
  CHECK_EQ("list madr end", D_MADR(0), 0x00FFFFFF);
  CHECK_EQ("list dicr", DICR, 0x81810000);
  mdec_idle_check("list words exact");
  DICR = 0x01000000;
}

int main(void) {
  test_otc();
  test_otc_needs_trigger();
  test_dicr_rules();
  test_otc_time();
  test_chopping();
  test_block_mode();
  test_linked_list();
  return test_done("dma_modes");
}
