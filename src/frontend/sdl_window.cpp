// The play window (sdl_window.h): an SDL renderer with one streaming texture for the picture,
// letterboxed to 4:3 when the user resizes the window.
#include "frontend/sdl_window.h"

#include <cstdlib>
#include <stdexcept>

#include "frontend/keymap.h"

namespace psxrl::frontend {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error(what + ": " + SDL_GetError()); }

bool env_set(const char* name) {
  const char* v = std::getenv(name);
  return v && *v;
}

}  // namespace

std::string display_problem() {
  if (env_set("SDL_VIDEODRIVER") || env_set("DISPLAY") || env_set("WAYLAND_DISPLAY")) return "";
  return "no display (DISPLAY and WAYLAND_DISPLAY are not set)";
}

WindowSize window_size(int width, int height, int scale) {
  if (scale <= 0) scale = height < 400 ? 2 : 1;
  int h = height * scale;
  return {h * 4 / 3, h};
}

SdlWindow::SdlWindow(const std::string& title, WindowSize size) {
  if (SDL_InitSubSystem(SDL_INIT_VIDEO | SDL_INIT_GAMECONTROLLER) != 0) fail("cannot start SDL video");
  try {
    open(title, size);
  } catch (...) {  // no destructor runs for a constructor that throws
    release();
    throw;
  }
}

void SdlWindow::open(const std::string& title, WindowSize size) {
  // Nearest-pixel scaling: an integer scale shows every console pixel as an exact square.
  SDL_SetHint(SDL_HINT_RENDER_SCALE_QUALITY, "nearest");
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, size.width, size.height,
                             SDL_WINDOW_RESIZABLE);
  if (!window_) fail("cannot open a window");
  // With DISPLAY naming a server that is not there (or refuses us), SDL falls back to a driver
  // that shows nothing: ask which one it chose. A driver named in SDL_VIDEODRIVER is the user's.
  const char* driver = SDL_GetCurrentVideoDriver();
  const std::string name = driver ? driver : "";
  if (!env_set("SDL_VIDEODRIVER") && (name == "offscreen" || name == "dummy" || name.empty())) {
    const char* display = std::getenv("DISPLAY");
    throw std::runtime_error("no display can show a window (DISPLAY=" + std::string(display ? display : "") +
                             " is unreachable; SDL fell back to its invisible '" + name + "' video driver)");
  }
  renderer_ = SDL_CreateRenderer(window_, -1, 0);
  if (!renderer_) fail("cannot create a renderer for the window");
  SDL_RenderSetLogicalSize(renderer_, size.width, size.height);
  // Gamepads are opened as SDL announces them: it sends SDL_CONTROLLERDEVICEADDED for those
  // present at start too.
}

SdlWindow::~SdlWindow() { release(); }

void SdlWindow::release() {
  for (SDL_GameController* c : controllers_) SDL_GameControllerClose(c);
  if (texture_) SDL_DestroyTexture(texture_);
  if (renderer_) SDL_DestroyRenderer(renderer_);
  if (window_) SDL_DestroyWindow(window_);
  SDL_QuitSubSystem(SDL_INIT_VIDEO | SDL_INIT_GAMECONTROLLER);
}

void SdlWindow::open_controller(int joystick_index) {
  if (!SDL_IsGameController(joystick_index)) return;
  if (SDL_GameController* c = SDL_GameControllerOpen(joystick_index)) controllers_.push_back(c);
}

void SdlWindow::close_controller(SDL_JoystickID id) {
  for (auto it = controllers_.begin(); it != controllers_.end(); ++it)
    if (SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(*it)) == id) {
      SDL_GameControllerClose(*it);
      controllers_.erase(it);
      return;
    }
}

void SdlWindow::show(const psx::u8* rgb, int width, int height, bool read_back) {
  if (!texture_ || width != texture_w_ || height != texture_h_) {
    if (texture_) SDL_DestroyTexture(texture_);
    texture_ = SDL_CreateTexture(renderer_, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STREAMING, width, height);
    if (!texture_) fail("cannot create a texture for the picture");
    texture_w_ = width;
    texture_h_ = height;
  }
  SDL_UpdateTexture(texture_, nullptr, rgb, width * 3);
  SDL_SetRenderDrawColor(renderer_, 0, 0, 0, 255);
  SDL_RenderClear(renderer_);
  SDL_RenderCopy(renderer_, texture_, nullptr, nullptr);
  if (read_back) {
    int w = 0, h = 0;
    SDL_RenderGetLogicalSize(renderer_, &w, &h);
    picture_.resize(static_cast<size_t>(w) * h * 3);
    if (SDL_RenderReadPixels(renderer_, nullptr, SDL_PIXELFORMAT_RGB24, picture_.data(), w * 3) != 0)
      fail("cannot read the window's picture back");
    picture_size_ = {w, h};
  }
  SDL_RenderPresent(renderer_);
}

WindowInput SdlWindow::poll() {
  WindowInput in;
  SDL_Event e;
  while (SDL_PollEvent(&e)) {
    if (e.type == SDL_QUIT) in.quit = true;
    if (e.type == SDL_CONTROLLERDEVICEADDED) open_controller(e.cdevice.which);
    if (e.type == SDL_CONTROLLERDEVICEREMOVED) close_controller(e.cdevice.which);
    if (e.type == SDL_KEYDOWN && !e.key.repeat) {
      KeyCommand c = key_command(e.key.keysym.sym);
      in.quit |= c == KeyCommand::Quit;
      in.toggle_pause |= c == KeyCommand::Pause;
      in.save_state |= c == KeyCommand::SaveState;
      if (int m = key_mark(e.key.keysym.sym)) in.mark = m;
    }
  }
  int count = 0;
  const Uint8* keys = SDL_GetKeyboardState(&count);
  for (int sc = 0; sc < count; ++sc)
    if (keys[sc]) in.buttons |= key_button(SDL_GetKeyFromScancode(static_cast<SDL_Scancode>(sc)));
  for (SDL_GameController* c : controllers_) {
    for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX; ++b)
      if (SDL_GameControllerGetButton(c, static_cast<SDL_GameControllerButton>(b)))
        in.buttons |= controller_button(static_cast<SDL_GameControllerButton>(b));
    for (auto axis : {SDL_CONTROLLER_AXIS_TRIGGERLEFT, SDL_CONTROLLER_AXIS_TRIGGERRIGHT})
      if (SDL_GameControllerGetAxis(c, axis) > 16384) in.buttons |= controller_trigger(axis);
  }
  return in;
}

void SdlWindow::set_title(const std::string& title) { SDL_SetWindowTitle(window_, title.c_str()); }

}  // namespace psxrl::frontend
