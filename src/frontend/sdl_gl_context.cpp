// SDL2 OpenGL context on a hidden window (sdl_gl_context.h).
#include "frontend/sdl_gl_context.h"

#include <SDL.h>

namespace psxrl::frontend {

std::unique_ptr<SdlGlContext> SdlGlContext::create(std::string& error) {
  std::unique_ptr<SdlGlContext> c(new SdlGlContext());
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
    error = std::string("SDL video: ") + SDL_GetError();
    return nullptr;
  }
  c->video_ = true;
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
  SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
  c->window_ = SDL_CreateWindow("psxrl OpenGL", 0, 0, 1, 1, SDL_WINDOW_OPENGL | SDL_WINDOW_HIDDEN);
  if (c->window_) c->context_ = SDL_GL_CreateContext(static_cast<SDL_Window*>(c->window_));
  // Later windows (the play window's SDL renderer) choose their own context attributes.
  SDL_GL_ResetAttributes();
  if (!c->context_) {
    error = std::string("SDL OpenGL 3.3 core context: ") + SDL_GetError();
    return nullptr;
  }
  return c;
}

SdlGlContext::~SdlGlContext() {
  if (context_) SDL_GL_DeleteContext(static_cast<SDL_GLContext>(context_));
  if (window_) SDL_DestroyWindow(static_cast<SDL_Window*>(window_));
  if (video_) SDL_QuitSubSystem(SDL_INIT_VIDEO);
}

void SdlGlContext::make_current() {
  if (SDL_GL_GetCurrentContext() != context_) SDL_GL_MakeCurrent(static_cast<SDL_Window*>(window_), context_);
}

void* SdlGlContext::proc_address(const char* name) { return SDL_GL_GetProcAddress(name); }

}  // namespace psxrl::frontend
