/* Tumble for the PlayStation: start-up without the BIOS (interrupts masked, VBlank polled), then
   one loop per video frame: read the pad, run one frame of the game logic, play its sounds and
   rumble, draw. The game state, whose first member is the RAM contract, is placed by the linker
   at 0x80010000 (tumble.ld). */
#include "game.h"
#include "gpu.h"
#include "hud.h"
#include "hw.h"
#include "pad.h"
#include "scene.h"
#include "screens.h"
#include "sound.h"

Game tumble_game __attribute__((section(".contract")));

static Gpu gpu;

/* 32x32 15-bit tile texture: a light bevel, a dark groove, a soft two-tone checker. */
static void upload_tile_texture(void) {
  static uint16_t texels[32 * 32];
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      int edge = x < 2 || y < 2 ? 31 : x > 29 || y > 29 ? 10 : ((x >> 3) ^ (y >> 3)) & 1 ? 22 : 19;
      texels[y * 32 + x] = (uint16_t)(edge | edge << 5 | edge << 10);
    }
  }
  gpu_upload(TILE_VRAM_X, 0, 32, 32, texels);
}

int main(void) {
  Pad pad;
  Sound sound;
  hw_init();
  gpu_init(&gpu);
  upload_tile_texture();
  hud_init();
  sound_init(&sound);
  pad_init(&pad);
  game_init(&tumble_game, 0x2545F491u);
  for (;;) {
    uint32_t buttons = pad_poll(&pad, tumble_game.rumble_frames ? 0xC0 : 0);
    game_frame(&tumble_game, buttons);
    scene_update_camera(&tumble_game);
    sound_play_events(&sound, tumble_game.pub.events);
    gpu_begin(&gpu);
    screens_draw(&gpu, &tumble_game);
    gpu_present(&gpu);
  }
}
