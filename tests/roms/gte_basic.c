/* GTE through the CPU: MTC2/MFC2, CTC2/CFC2, LWC2/SWC2 and commands issued as COP2 instructions,
   including a command immediately followed by a read (the CPU must stall until it finishes),
   and RTPT of a cube with screen coordinates worked out by hand (psx-spx "GTE" chapters). */
#include <stdint.h>

#include "psx/test.h"

/* Every access is written in a noreorder block so the instruction sequence is exactly what the
   test means: MFC2/CFC2 results are used only after their load-delay slot; writes get the two
   NOPs that Sony's GTE macros put before a command. */
#define GTE_MTC2(value, reg) \
  __asm__ volatile(".set push\n.set noreorder\nmtc2 %0, $" #reg "\nnop\nnop\n.set pop" ::"r"(value))
#define GTE_CTC2(value, reg) \
  __asm__ volatile(".set push\n.set noreorder\nctc2 %0, $" #reg "\nnop\nnop\n.set pop" ::"r"(value))
#define GTE_MFC2(reg)                                                                            \
  ({                                                                                             \
    uint32_t v_;                                                                                 \
    __asm__ volatile(".set push\n.set noreorder\nmfc2 %0, $" #reg "\nnop\n.set pop" : "=r"(v_)); \
    v_;                                                                                          \
  })
#define GTE_CFC2(reg)                                                                            \
  ({                                                                                             \
    uint32_t v_;                                                                                 \
    __asm__ volatile(".set push\n.set noreorder\ncfc2 %0, $" #reg "\nnop\n.set pop" : "=r"(v_)); \
    v_;                                                                                          \
  })
/* A command word is "cop2 imm25" (0x4A000000 | imm25); bits 20-24 are ignored by the GTE and
   hold Sony's customary values. */
#define STR_(x) #x
#define STR(x) STR_(x)
#define CMD_RTPT 0x0280030  /* sf=1 */
#define CMD_NCLIP 0x1400006
#define CMD_AVSZ3 0x158002D
#define CMD_SQR 0x0A80428   /* sf=1, lm=1 */
#define GTE_CMD(imm25) __asm__ volatile(".set push\n.set noreorder\nnop\nnop\ncop2 " STR(imm25) "\n.set pop")

static void enable_cop2(void) {
  uint32_t sr;
  __asm__ volatile(".set push\n.set noreorder\nmfc0 %0, $12\nnop\n.set pop" : "=r"(sr));
  sr |= 1u << 30; /* SR.CU2 */
  __asm__ volatile(".set push\n.set noreorder\nmtc0 %0, $12\nnop\nnop\n.set pop" ::"r"(sr));
}

static void test_data_registers(void) {
  GTE_MTC2(0x12345678u, 0); /* VXY0: both halves kept */
  CHECK_EQ("VXY0", GTE_MFC2(0), 0x12345678u);
  GTE_MTC2(0x00018000u, 1); /* VZ0 is 16-bit signed: reads FFFF8000 */
  CHECK_EQ("VZ0 sign-extends", GTE_MFC2(1), 0xFFFF8000u);
  GTE_MTC2(0xFFFF8000u, 7); /* OTZ is 16-bit unsigned */
  CHECK_EQ("OTZ zero-extends", GTE_MFC2(7), 0x8000u);
  GTE_MTC2(0x7C21u, 28); /* IRGB R=1, G=1, B=1Fh -> IR = 80h, 80h, F80h */
  CHECK_EQ("IRGB->IR1", GTE_MFC2(9), 0x80u);
  CHECK_EQ("IRGB->IR3", GTE_MFC2(11), 0xF80u);
  CHECK_EQ("ORGB", GTE_MFC2(29), 0x7C21u);
  GTE_MTC2(0x00001000u, 30); /* LZCS: first set bit is bit 12 -> 19 leading zeros */
  CHECK_EQ("LZCR positive", GTE_MFC2(31), 19u);
  GTE_MTC2(0xFFF00000u, 30); /* 12 leading ones */
  CHECK_EQ("LZCR negative", GTE_MFC2(31), 12u);
  GTE_MTC2(0x00010001u, 12);
  GTE_MTC2(0x00020002u, 13);
  GTE_MTC2(0x00030003u, 14);
  GTE_MTC2(0x00040004u, 15); /* SXYP pushes the FIFO */
  CHECK_EQ("SXYP push SXY0", GTE_MFC2(12), 0x00020002u);
  CHECK_EQ("SXYP reads SXY2", GTE_MFC2(15), 0x00040004u);
}

static void test_control_registers(void) {
  GTE_CTC2(0x5555AAAAu, 4); /* RT33 alone in its word: reads sign-extended */
  CHECK_EQ("RT33", GTE_CFC2(4), 0xFFFFAAAAu);
  GTE_CTC2(0x00008000u, 26); /* H reads sign-extended although it is unsigned */
  CHECK_EQ("H", GTE_CFC2(26), 0xFFFF8000u);
  GTE_CTC2(0x00400000u, 31); /* FLAG bit 22 (IR3) is not an error bit */
  CHECK_EQ("FLAG no error", GTE_CFC2(31), 0x00400000u);
  GTE_CTC2(0x00800FFFu, 31); /* bit 23 (IR2) is; bits 0-11 read 0 */
  CHECK_EQ("FLAG bit 31", GTE_CFC2(31), 0x80800000u);
}

/* A command immediately followed by a read: SQR takes 5 cycles, MFC2 must wait for IR1. */
static void test_command_then_read(void) {
  uint32_t ir1;
  GTE_MTC2(0x2000u, 9); /* IR1 = 2.0 in 4.12; SQR sf=1: 2000h*2000h >> 12 = 4000h */
  __asm__ volatile(".set push\n.set noreorder\nnop\nnop\ncop2 " STR(CMD_SQR) "\nmfc2 %0, $9\nnop\n.set pop"
                   : "=r"(ir1));
  CHECK_EQ("SQR then MFC2", ir1, 0x4000u);
}

/* Cube of side 1000 centred 1500 in front of the camera: RT = identity (1000h), TR = (0,0,1500),
   H = 1000, OFX = 160, OFY = 120 (16.16), sf=1, vertices (+-500, +-500, +-500).
   Front face z = 1500-500 = 1000: SZ3 = 1000 and H/SZ3 = 1000/1000. Division: SZ3 = 3E8h has 6
   leading zeros, so n = d = FA00h; table index (FA00h-7FC0h)>>7 = F4h, unr_table[F4h] =
   (40000h/1F4h+1)/2-101h = (524+1)/2-257 = 5, u = 106h; d = (2000080h-FA00h*106h)>>8 = 65572;
   d = (80h+65572*262)>>8 = 67109; (FA00h*67109+8000h)>>16 = 10000h (exactly 1.0).
     SX = (10000h*(+-500) + A00000h) >> 16 = 160 +- 500 = 660 or -340
     SY = (10000h*(+-500) + 780000h) >> 16 = 120 +- 500 = 620 or -380
   Back face z = 2000: SZ3 = 7D0h has 5 leading zeros, d = FA00h again, n = 7D00h:
   (7D00h*67109+8000h)>>16 = 8000h (exactly 0.5).
     SX = (8000h*(+-500) + A00000h) >> 16 = 160 +- 250 = 410 or -90
     SY = (8000h*(+-500) + 780000h) >> 16 = 120 +- 250 = 370 or -130 */
static const int16_t cube_front[3][4] = {{-500, -500, -500, 0}, {500, -500, -500, 0}, {-500, 500, -500, 0}};
static const int16_t cube_back[3][4] = {{-500, -500, 500, 0}, {500, -500, 500, 0}, {500, 500, 500, 0}};

#define SXY(x, y) (((uint32_t)(uint16_t)(y) << 16) | (uint16_t)(x))

static void setup_camera(void) {
  GTE_CTC2(0x00001000u, 0); /* RT11 = 1.0, RT12 = 0 */
  GTE_CTC2(0x00000000u, 1); /* RT13, RT21 */
  GTE_CTC2(0x00001000u, 2); /* RT22 = 1.0, RT23 = 0 */
  GTE_CTC2(0x00000000u, 3); /* RT31, RT32 */
  GTE_CTC2(0x00001000u, 4); /* RT33 = 1.0 */
  GTE_CTC2(0u, 5);
  GTE_CTC2(0u, 6);
  GTE_CTC2(1500u, 7);      /* TRZ */
  GTE_CTC2(160u << 16, 24); /* OFX */
  GTE_CTC2(120u << 16, 25); /* OFY */
  GTE_CTC2(1000u, 26);      /* H */
  GTE_CTC2(0u, 27);         /* DQA */
  GTE_CTC2(0u, 28);         /* DQB */
  GTE_CTC2(0x555u, 29);     /* ZSF3 ~ 1/3 */
}

/* LWC2 the three vertices (VXY0, VZ0, ... VZ2) straight from memory. */
static void load_vertices(const int16_t v[3][4]) {
  __asm__ volatile(
      ".set push\n.set noreorder\n"
      "lwc2 $0, 0(%0)\nlwc2 $1, 4(%0)\nlwc2 $2, 8(%0)\nlwc2 $3, 12(%0)\nlwc2 $4, 16(%0)\nlwc2 $5, 20(%0)\n"
      "nop\nnop\n.set pop" ::"r"(v)
      : "memory");
}

/* RTPT, then SWC2 of the screen FIFO straight away (the stores wait for the command). */
static void rtpt_store(uint32_t out[3]) {
  __asm__ volatile(
      ".set push\n.set noreorder\nnop\nnop\ncop2 " STR(CMD_RTPT) "\n"
      "swc2 $12, 0(%0)\nswc2 $13, 4(%0)\nswc2 $14, 8(%0)\n.set pop" ::"r"(out)
      : "memory");
}

static void test_cube(void) {
  uint32_t sxy[3];
  setup_camera();
  load_vertices(cube_front);
  CHECK_EQ("LWC2 VXY1", GTE_MFC2(2), SXY(500, -500));
  CHECK_EQ("LWC2 VZ2", GTE_MFC2(5), 0xFFFFFE0Cu); /* -500 */
  rtpt_store(sxy);
  CHECK_EQ("front SXY0", sxy[0], SXY(-340, -380));
  CHECK_EQ("front SXY1", sxy[1], SXY(660, -380));
  CHECK_EQ("front SXY2", sxy[2], SXY(-340, 620));
  CHECK_EQ("front SZ3", GTE_MFC2(19), 1000u);
  CHECK_EQ("front FLAG", GTE_CFC2(31), 0u);
  /* NCLIP = (x1-x0)*(y2-y0) - (x2-x0)*(y1-y0) = 1000*1000 - 0*0 */
  GTE_CMD(CMD_NCLIP);
  CHECK_EQ("NCLIP", GTE_MFC2(24), 1000000u);
  /* AVSZ3 = 555h*(1000+1000+1000) = 4095000; OTZ = 4095000>>12 = 999 */
  GTE_CMD(CMD_AVSZ3);
  CHECK_EQ("AVSZ3 MAC0", GTE_MFC2(24), 4095000u);
  CHECK_EQ("AVSZ3 OTZ", GTE_MFC2(7), 999u);

  load_vertices(cube_back);
  rtpt_store(sxy);
  CHECK_EQ("back SXY0", sxy[0], SXY(-90, -130));
  CHECK_EQ("back SXY1", sxy[1], SXY(410, -130));
  CHECK_EQ("back SXY2", sxy[2], SXY(410, 370));
  CHECK_EQ("back SZ3", GTE_MFC2(19), 2000u);
  CHECK_EQ("back SZ0", GTE_MFC2(16), 1000u); /* last front-face depth, three pushes ago */
  /* MAC1..3 hold the last vertex in view space: (500, 500, 2000) */
  CHECK_EQ("back MAC3", GTE_MFC2(27), 2000u);
  CHECK_EQ("back IR1", GTE_MFC2(9), 500u);
}

int main(void) {
  enable_cop2();
  test_data_registers();
  test_control_registers();
  test_command_then_read();
  test_cube();
  return test_done("gte_basic");
}
