/* Game events to sound effects (see sound.h). */
#include "sound.h"
#include "contract.h"
#include "spu.h"

void sound_init(Sound *sound) {
  sound->next_voice = 0;
  spu_init();
  spu_upload(SPU_SAMPLE_BASE, tumble_sfx_adpcm, tumble_sfx_bytes);
}

static void play(Sound *sound, int sfx) {
  const SfxInfo *info = &tumble_sfx[sfx];
  spu_play((int)sound->next_voice, SPU_SAMPLE_BASE + info->offset, info->pitch, 0x3000);
  sound->next_voice = (sound->next_voice + 1) & 7;
}

void sound_play_events(Sound *sound, uint32_t events) {
  static const struct { uint32_t event; uint8_t sfx; } map[] = {
    {TUMBLE_EV_ROLL, SFX_ROLL},       {TUMBLE_EV_TURN, SFX_TURN},       {TUMBLE_EV_JUMP, SFX_JUMP},
    {TUMBLE_EV_COIN, SFX_COIN},       {TUMBLE_EV_FRUIT, SFX_FRUIT},     {TUMBLE_EV_KEY, SFX_KEY},
    {TUMBLE_EV_FALL, SFX_FALL},       {TUMBLE_EV_SPIKED, SFX_SPIKED},   {TUMBLE_EV_TIME_UP, SFX_FALL},
    {TUMBLE_EV_WIN, SFX_WIN},         {TUMBLE_EV_CRUMBLE_WARN, SFX_CRUMBLE},
    {TUMBLE_EV_CRUMBLE_BREAK, SFX_CRUMBLE}, {TUMBLE_EV_MENU, SFX_MENU},
  };
  for (unsigned i = 0; i < sizeof map / sizeof map[0]; ++i)
    if (events & map[i].event) play(sound, map[i].sfx);
}
