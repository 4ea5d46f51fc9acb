/* PlayStation I/O registers Tumble uses (names and addresses from psx-spx "Memory Map" / "I/O
   Map"), read and written through the uncached KSEG1 mirror, plus the few system helpers in hw.c:
   interrupts off, VBlank by polling I_STAT, DMA channel set-up. No BIOS call anywhere. */
#ifndef TUMBLE_HW_H
#define TUMBLE_HW_H
#include <stdint.h>

#define IO32(a) (*(volatile uint32_t *)(0xBF800000u + (a)))
#define IO16(a) (*(volatile uint16_t *)(0xBF800000u + (a)))
#define IO8(a) (*(volatile uint8_t *)(0xBF800000u + (a)))

/* Interrupt controller */
#define I_STAT IO32(0x1070)
#define I_MASK IO32(0x1074)
#define IRQ_VBLANK (1u << 0)
#define IRQ_CONTROLLER (1u << 7)

/* DMA: channel n registers at 1F801080h + n*10h; DPCR enables, DICR interrupts. */
#define DMA_MADR(n) IO32(0x1080 + (n) * 0x10)
#define DMA_BCR(n) IO32(0x1084 + (n) * 0x10)
#define DMA_CHCR(n) IO32(0x1088 + (n) * 0x10)
#define DMA_DPCR IO32(0x10F0)
#define DMA_DICR IO32(0x10F4)
#define DMA_GPU 2
#define DMA_SPU 4
#define DMA_OTC 6
#define CHCR_BUSY (1u << 24)

/* GPU */
#define GPU_GP0 IO32(0x1810)
#define GPU_GP1 IO32(0x1814)
#define GPU_STAT IO32(0x1814)
#define GPUSTAT_READY_CMD (1u << 26)
#define GPUSTAT_READY_DMA (1u << 28)

/* Controller and memory card serial port SIO0 */
#define JOY_DATA IO8(0x1040)
#define JOY_STAT IO32(0x1044)
#define JOY_MODE IO16(0x1048)
#define JOY_CTRL IO16(0x104A)
#define JOY_BAUD IO16(0x104E)

/* SPU */
#define SPU_VOICE(v, r) IO16(0x1C00 + (v) * 0x10 + (r))
#define SPU_MAIN_VOL_L IO16(0x1D80)
#define SPU_MAIN_VOL_R IO16(0x1D82)
#define SPU_REVERB_VOL_L IO16(0x1D84)
#define SPU_REVERB_VOL_R IO16(0x1D86)
#define SPU_KON_LO IO16(0x1D88)
#define SPU_KON_HI IO16(0x1D8A)
#define SPU_KOFF_LO IO16(0x1D8C)
#define SPU_KOFF_HI IO16(0x1D8E)
#define SPU_PMON_LO IO16(0x1D90)
#define SPU_NON_LO IO16(0x1D94)
#define SPU_EON_LO IO16(0x1D98)
#define SPU_EON_HI IO16(0x1D9A)
#define SPU_TRANSFER_ADDR IO16(0x1DA6)
#define SPU_FIFO IO16(0x1DA8)
#define SPU_CNT IO16(0x1DAA)
#define SPU_TRANSFER_CTRL IO16(0x1DAC)
#define SPU_STAT IO16(0x1DAE)
#define SPU_CD_VOL_L IO16(0x1DB0)
#define SPU_CD_VOL_R IO16(0x1DB2)

/* Masks CPU interrupts (COP0 SR.IEc = 0) and every I_MASK line, so no BIOS handler ever runs;
   enables COP2 (the GTE) in SR.CU2. */
void hw_init(void);
/* Waits for the next vertical blank by polling I_STAT bit 0, then acknowledges it. */
void hw_wait_vblank(void);
/* Waits until DMA channel `ch` has finished (CHCR bit 24 clear), with a bounded spin. */
void hw_wait_dma(int ch);

#endif
