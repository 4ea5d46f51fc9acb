/* Geometry Transformation Engine (COP2) access by inline assembly, register numbers and command
   words from psx-spx "Geometry Transformation Engine": rotation RT (control 0-4), translation TR
   (5-7), screen offset OFX/OFY (24-25, 16.16), projection plane distance H (26), average-Z
   scales ZSF3/ZSF4 (29-30); input vectors V0-V2 (data 0-5), results SXY0-2 (12-14), SZ1-3
   (17-19), MAC0 (24), OTZ (7). Commands: RTPS/RTPT (perspective transform of one/three
   vertices), NCLIP (winding of SXY0-2 in MAC0), AVSZ3/AVSZ4 (ordering-table depth in OTZ).
   Each mtc2/ctc2 is followed by nops so a command never sees a stale input (GTE load delay). */
#ifndef TUMBLE_GTE_H
#define TUMBLE_GTE_H
#include <stdint.h>

#define GTE_RTPS 0x0180001
#define GTE_RTPT 0x0280030
#define GTE_NCLIP 0x1400006
#define GTE_AVSZ3 0x158002D
#define GTE_AVSZ4 0x168002E

#define GTE_STR(x) #x
#define GTE_XSTR(x) GTE_STR(x)

#define gte_ctc2(value, reg) \
  __asm__ volatile("ctc2 %0, $" #reg "\n\tnop\n\tnop" : : "r"((uint32_t)(value)))
#define gte_mtc2(value, reg) \
  __asm__ volatile("mtc2 %0, $" #reg "\n\tnop\n\tnop" : : "r"((uint32_t)(value)))
#define gte_mfc2(reg) ({ uint32_t v_; __asm__ volatile("mfc2 %0, $" #reg "\n\tnop" : "=r"(v_)); v_; })
#define gte_cmd(cmd) __asm__ volatile("nop\n\tnop\n\tcop2 " GTE_XSTR(cmd) "\n\tnop\n\tnop" : : : "memory")

static inline uint32_t gte_pack_xy(int32_t x, int32_t y) { return ((uint32_t)y << 16) | ((uint32_t)x & 0xFFFF); }

/* Loads vertex `n` (0..2) of the next RTPS/RTPT. */
static inline void gte_load_v0(int32_t x, int32_t y, int32_t z) { gte_mtc2(gte_pack_xy(x, y), 0); gte_mtc2(z, 1); }
static inline void gte_load_v1(int32_t x, int32_t y, int32_t z) { gte_mtc2(gte_pack_xy(x, y), 2); gte_mtc2(z, 3); }
static inline void gte_load_v2(int32_t x, int32_t y, int32_t z) { gte_mtc2(gte_pack_xy(x, y), 4); gte_mtc2(z, 5); }

#endif
