// The play window (SDL2): shows the console's displayed picture at 4:3 and an integer multiple
// of its size (320x240 -> 640x480), reads the keyboard and gamepads, and can read back what it
// drew (for tests and window screenshots). It only displays: the emulation never waits on it.
#pragma once
#include <SDL.h>

#include <string>
#include <vector>

#include "core/types.h"

namespace psxrl::frontend {

// Why no window can be opened here, or "" when a display seems available: no X11 or Wayland
// display named in the environment (SDL would otherwise pick its invisible "offscreen" driver),
// unless SDL_VIDEODRIVER names a driver on purpose.
std::string display_problem();

// Window size for a displayed area of `width` x `height`: the height times `scale` (0: 2 for
// pictures under 400 lines, else 1) and 4:3 around it.
struct WindowSize {
  int width, height;
};
WindowSize window_size(int width, int height, int scale);

// What the player did since the last poll.
struct WindowInput {
  psx::u16 buttons = 0;  // pad_button bits held now (keyboard and gamepads together)
  bool quit = false;
  bool toggle_pause = false;
  bool save_state = false;
  int mark = 0;  // F1..F4 pressed: 1..4 (the last one when several were)
};

class SdlWindow {
 public:
  // Opens the window; throws std::runtime_error with SDL's reason when it cannot, or when SDL
  // could open it only on an invisible driver ("offscreen", "dummy") it fell back to by itself.
  SdlWindow(const std::string& title, WindowSize size);
  ~SdlWindow();
  SdlWindow(const SdlWindow&) = delete;
  SdlWindow& operator=(const SdlWindow&) = delete;

  // Draws `width` x `height` RGB888 pixels stretched over the window (nearest pixel, so an
  // integer scale repeats each pixel exactly). With `read_back`, what was drawn is kept for
  // picture() before it is presented (the presented buffer cannot be read afterwards).
  void show(const psx::u8* rgb, int width, int height, bool read_back = false);
  // The last picture read back by show(): RGB888 rows of picture_size().
  const std::vector<psx::u8>& picture() const { return picture_; }
  WindowSize picture_size() const { return picture_size_; }

  WindowInput poll();
  void set_title(const std::string& title);

 private:
  void open(const std::string& title, WindowSize size);
  void release();
  void open_controller(int joystick_index);
  void close_controller(SDL_JoystickID id);

  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  SDL_Texture* texture_ = nullptr;
  int texture_w_ = 0, texture_h_ = 0;
  std::vector<SDL_GameController*> controllers_;
  std::vector<psx::u8> picture_;
  WindowSize picture_size_{0, 0};
};

}  // namespace psxrl::frontend
