/* SPU access (psx-spx "Sound Processing Unit"): power-up, sample upload to SPU RAM by manual
   FIFO writes, and one-shot voice playback. */
#ifndef TUMBLE_SPU_H
#define TUMBLE_SPU_H
#include <stdint.h>

/* First SPU RAM byte free for samples (below: capture buffers; psx-spx SPU memory layout). */
#define SPU_SAMPLE_BASE 0x1010

void spu_init(void);
/* Writes `bytes` (a multiple of 2) to SPU RAM at byte address `addr` (a multiple of 8). */
void spu_upload(uint32_t addr, const uint8_t *data, uint32_t bytes);
/* Plays the sample at SPU RAM byte address `addr` on `voice` once. */
void spu_play(int voice, uint32_t addr, uint32_t pitch, uint16_t volume);

#endif
