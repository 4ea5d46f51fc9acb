// Human play's controls: which keyboard keys and gamepad buttons (SDL GameController API) press
// which PlayStation pad buttons, and the keys that control the player itself (pause, save a
// level-start state, quit). docs/play.md lists the same mapping for users.
#pragma once
#include <SDL.h>

#include "core/types.h"

namespace psxrl::frontend {

// Commands for the player, not for the console.
enum class KeyCommand { None, Quit, Pause, SaveState };

// The pad_button bit (core/sio/pad.h) a key presses, or 0.
psx::u16 key_button(SDL_Keycode key);
// The pad_button bit a gamepad button presses, or 0.
psx::u16 controller_button(SDL_GameControllerButton button);
// The pad_button bit an analog trigger (L2/R2) presses when held past half way, or 0.
psx::u16 controller_trigger(SDL_GameControllerAxis axis);
KeyCommand key_command(SDL_Keycode key);
// F1..F4 set marks 1..4 while recording a session (psxrl record); 0 for other keys.
int key_mark(SDL_Keycode key);

// The mapping as text, for `psxrl play --help`.
extern const char* const kControlsHelp;

}  // namespace psxrl::frontend
