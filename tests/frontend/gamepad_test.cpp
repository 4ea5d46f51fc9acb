// Gamepads in the play window, through SDL's virtual joystick (a game controller that SDL
// announces and maps like a real one): buttons and triggers reach the pad bits of docs/play.md.
// Needs a display for the window (CTest runs PlayWindow.* under xvfb-run).
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/sio/pad.h"
#include "frontend/sdl_window.h"

namespace {

namespace b = psx::pad_button;
using psxrl::frontend::SdlWindow;

TEST(PlayWindow, AGamepadPressesPadButtons) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run (CTest does)";
  SdlWindow window("psxrl gamepad test", {640, 480});
  int index = SDL_JoystickAttachVirtual(SDL_JOYSTICK_TYPE_GAMECONTROLLER, SDL_CONTROLLER_AXIS_MAX,
                                        SDL_CONTROLLER_BUTTON_MAX, 0);
  ASSERT_GE(index, 0) << SDL_GetError();
  SDL_Joystick* stick = SDL_JoystickOpen(index);
  ASSERT_NE(stick, nullptr) << SDL_GetError();
  EXPECT_EQ(window.poll().buttons, 0);  // the window opens the announced controller
  SDL_JoystickSetVirtualButton(stick, SDL_CONTROLLER_BUTTON_A, 1);
  SDL_JoystickSetVirtualButton(stick, SDL_CONTROLLER_BUTTON_DPAD_LEFT, 1);
  // A virtual stick's axes span -32768..32767; SDL maps a trigger's to 0..32767 (released at
  // -32768). The right trigger is pulled all the way, the left a quarter: not pressed.
  SDL_JoystickSetVirtualAxis(stick, SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 32767);
  SDL_JoystickSetVirtualAxis(stick, SDL_CONTROLLER_AXIS_TRIGGERLEFT, -16384);
  EXPECT_EQ(window.poll().buttons, b::kCross | b::kLeft | b::kR2);
  SDL_GameController* pad = SDL_GameControllerOpen(index);
  EXPECT_LT(SDL_GameControllerGetAxis(pad, SDL_CONTROLLER_AXIS_TRIGGERLEFT), 16384);
  SDL_GameControllerClose(pad);
  SDL_JoystickSetVirtualButton(stick, SDL_CONTROLLER_BUTTON_A, 0);
  EXPECT_EQ(window.poll().buttons, b::kLeft | b::kR2);
  SDL_JoystickClose(stick);
  SDL_JoystickDetachVirtual(index);
}

}  // namespace
