// The play window's size rule and the documented controls (docs/play.md, keymap.h): every
// PlayStation button is reachable from the keyboard and from a gamepad, each by exactly one key.
#include <gtest/gtest.h>

#include "core/sio/pad.h"
#include "frontend/keymap.h"
#include "frontend/sdl_window.h"

namespace {

using namespace psxrl::frontend;
namespace b = psx::pad_button;

TEST(WindowSize, IsFourToThreeAtAnIntegerMultipleOfTheLines) {
  // 320x240 doubled is 640x480, itself 4:3: every pixel a 2x2 square.
  EXPECT_EQ(window_size(320, 240, 0).width, 640);
  EXPECT_EQ(window_size(320, 240, 0).height, 480);
  // 256 or 640 pixels wide (psx-spx "GPU Display Control" horizontal resolutions): still 4:3.
  EXPECT_EQ(window_size(256, 240, 0).width, 640);
  EXPECT_EQ(window_size(640, 480, 0).height, 480);
  EXPECT_EQ(window_size(368, 240, 3).width, 960);
  EXPECT_EQ(window_size(368, 240, 3).height, 720);
}

TEST(Keymap, ArrowsAreTheDpadAndEveryButtonHasOneKey) {
  EXPECT_EQ(key_button(SDLK_UP), b::kUp);
  EXPECT_EQ(key_button(SDLK_DOWN), b::kDown);
  EXPECT_EQ(key_button(SDLK_LEFT), b::kLeft);
  EXPECT_EQ(key_button(SDLK_RIGHT), b::kRight);
  EXPECT_EQ(key_button(SDLK_x), b::kCross);
  EXPECT_EQ(key_button(SDLK_RETURN), b::kStart);
  psx::u16 all = 0;
  int keys = 0;
  for (SDL_Keycode k = 0; k < 128; ++k) keys += key_button(k) != 0, all |= key_button(k);
  for (SDL_Keycode k : {SDLK_UP, SDLK_DOWN, SDLK_LEFT, SDLK_RIGHT}) keys += 1, all |= key_button(k);
  // Sixteen pad bits less L3 and R3 (a digital pad has no sticks): 14 buttons, 14 keys.
  EXPECT_EQ(all, static_cast<psx::u16>(~(b::kL3 | b::kR3)));
  EXPECT_EQ(keys, 14);
}

TEST(Keymap, AGamepadReachesEveryButton) {
  psx::u16 all = 0;
  for (int i = 0; i < SDL_CONTROLLER_BUTTON_MAX; ++i)
    all |= controller_button(static_cast<SDL_GameControllerButton>(i));
  all |= controller_trigger(SDL_CONTROLLER_AXIS_TRIGGERLEFT) | controller_trigger(SDL_CONTROLLER_AXIS_TRIGGERRIGHT);
  EXPECT_EQ(all, 0xFFFF);
  EXPECT_EQ(controller_button(SDL_CONTROLLER_BUTTON_A), b::kCross);  // the bottom face button
}

TEST(Keymap, PlayerCommands) {
  EXPECT_EQ(key_command(SDLK_ESCAPE), KeyCommand::Quit);
  EXPECT_EQ(key_command(SDLK_p), KeyCommand::Pause);
  EXPECT_EQ(key_command(SDLK_SPACE), KeyCommand::Pause);
  EXPECT_EQ(key_command(SDLK_F5), KeyCommand::SaveState);
  EXPECT_EQ(key_button(SDLK_p), 0);  // no key is both
  EXPECT_EQ(key_button(SDLK_SPACE), 0);
  // F1..F4 set marks 1..4 while recording (docs/play.md); they press no pad button.
  EXPECT_EQ(key_mark(SDLK_F1), 1);
  EXPECT_EQ(key_mark(SDLK_F4), 4);
  EXPECT_EQ(key_mark(SDLK_F5), 0);
  EXPECT_EQ(key_button(SDLK_F1), 0);
  EXPECT_EQ(key_command(SDLK_F1), KeyCommand::None);
}

}  // namespace
