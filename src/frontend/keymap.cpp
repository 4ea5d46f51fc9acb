// Human play's keyboard and gamepad mapping (keymap.h). The keyboard layout follows the usual
// emulator one: arrows for the d-pad and the bottom-left letter row for the face buttons, in the
// pad's own left-to-right order (Square, Cross, Circle) with Triangle above.
#include "frontend/keymap.h"

#include "core/sio/pad.h"

namespace psxrl::frontend {

namespace b = psx::pad_button;

psx::u16 key_button(SDL_Keycode key) {
  switch (key) {
    case SDLK_UP: return b::kUp;
    case SDLK_DOWN: return b::kDown;
    case SDLK_LEFT: return b::kLeft;
    case SDLK_RIGHT: return b::kRight;
    case SDLK_z: return b::kSquare;
    case SDLK_x: return b::kCross;
    case SDLK_c: return b::kCircle;
    case SDLK_s: return b::kTriangle;
    case SDLK_q: return b::kL1;
    case SDLK_w: return b::kR1;
    case SDLK_1: return b::kL2;
    case SDLK_2: return b::kR2;
    case SDLK_RETURN: return b::kStart;
    case SDLK_BACKSPACE: return b::kSelect;
    default: return 0;
  }
}

psx::u16 controller_button(SDL_GameControllerButton button) {
  // SDL names buttons by position on an Xbox-style pad: A is the bottom face button (Cross).
  switch (button) {
    case SDL_CONTROLLER_BUTTON_A: return b::kCross;
    case SDL_CONTROLLER_BUTTON_B: return b::kCircle;
    case SDL_CONTROLLER_BUTTON_X: return b::kSquare;
    case SDL_CONTROLLER_BUTTON_Y: return b::kTriangle;
    case SDL_CONTROLLER_BUTTON_LEFTSHOULDER: return b::kL1;
    case SDL_CONTROLLER_BUTTON_RIGHTSHOULDER: return b::kR1;
    case SDL_CONTROLLER_BUTTON_LEFTSTICK: return b::kL3;
    case SDL_CONTROLLER_BUTTON_RIGHTSTICK: return b::kR3;
    case SDL_CONTROLLER_BUTTON_START: return b::kStart;
    case SDL_CONTROLLER_BUTTON_BACK: return b::kSelect;
    case SDL_CONTROLLER_BUTTON_DPAD_UP: return b::kUp;
    case SDL_CONTROLLER_BUTTON_DPAD_DOWN: return b::kDown;
    case SDL_CONTROLLER_BUTTON_DPAD_LEFT: return b::kLeft;
    case SDL_CONTROLLER_BUTTON_DPAD_RIGHT: return b::kRight;
    default: return 0;
  }
}

psx::u16 controller_trigger(SDL_GameControllerAxis axis) {
  if (axis == SDL_CONTROLLER_AXIS_TRIGGERLEFT) return b::kL2;
  if (axis == SDL_CONTROLLER_AXIS_TRIGGERRIGHT) return b::kR2;
  return 0;
}

KeyCommand key_command(SDL_Keycode key) {
  switch (key) {
    case SDLK_ESCAPE: return KeyCommand::Quit;
    case SDLK_p:
    case SDLK_SPACE: return KeyCommand::Pause;
    case SDLK_F5: return KeyCommand::SaveState;
    default: return KeyCommand::None;
  }
}

int key_mark(SDL_Keycode key) {
  switch (key) {
    case SDLK_F1: return 1;
    case SDLK_F2: return 2;
    case SDLK_F3: return 3;
    case SDLK_F4: return 4;
    default: return 0;
  }
}

const char* const kControlsHelp =
    "controls (human play, in the window):\n"
    "  arrows     d-pad             Z  Square      X  Cross      C  Circle     S  Triangle\n"
    "  Q  L1      W  R1             1  L2          2  R2\n"
    "  Enter      Start             Backspace  Select\n"
    "  P or Space pause/resume      F5  save the level-start state (levels that start from states)\n"
    "  F1 to F4   set a mark (psxrl record: --mark-labels names them)\n"
    "  Escape or closing the window quits\n"
    "  a gamepad (SDL GameController): A Cross, B Circle, X Square, Y Triangle, shoulders L1/R1,\n"
    "  triggers L2/R2, Back Select, Start Start, d-pad, stick clicks L3/R3\n";

}  // namespace psxrl::frontend
