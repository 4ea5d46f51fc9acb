/* Sound effects: the ADPCM samples generated at build time (tools/sfxgen.c), their placement in
   SPU RAM, and which game events play which effect. */
#ifndef TUMBLE_SOUND_H
#define TUMBLE_SOUND_H
#include <stdint.h>

/* Order matches tools/sfxgen.c. */
enum Sfx { SFX_ROLL, SFX_TURN, SFX_JUMP, SFX_COIN, SFX_FRUIT, SFX_KEY, SFX_FALL, SFX_SPIKED, SFX_WIN,
           SFX_CRUMBLE, SFX_MENU, SFX_COUNT };

typedef struct SfxInfo {
  uint32_t offset; /* bytes into tumble_sfx_adpcm */
  uint32_t bytes;
  uint32_t pitch;  /* SPU pitch register value (1000h = 44100 Hz) */
} SfxInfo;

extern const uint8_t tumble_sfx_adpcm[];
extern const SfxInfo tumble_sfx[SFX_COUNT];
extern const uint32_t tumble_sfx_bytes;

typedef struct Sound {
  uint32_t next_voice; /* effects rotate over voices 0..7 */
} Sound;

void sound_init(Sound *sound);
/* Starts the effects for a frame's TUMBLE_EV_* bits. */
void sound_play_events(Sound *sound, uint32_t events);

#endif
