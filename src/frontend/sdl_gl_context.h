// An OpenGL 3.3 core context from SDL2, for the OpenGL renderer when a display exists (psxrl play
// with its window): the desktop's own OpenGL driver, often a GPU, instead of OSMesa's software
// one. It lives on a hidden 1x1 window of its own, so the play window keeps its SDL renderer;
// the renderer draws only into its textures and the picture reaches the window as before.
#pragma once
#include <memory>
#include <string>

#include "gpu/gl/gl_context.h"

namespace psxrl::frontend {

class SdlGlContext final : public psx::gpu::gl::GlContext {
 public:
  // Null with `error` set when SDL has no video, no OpenGL or no 3.3 core context.
  static std::unique_ptr<SdlGlContext> create(std::string& error);
  ~SdlGlContext() override;

  void make_current() override;
  void* proc_address(const char* name) override;
  std::string name() const override { return "SDL2 OpenGL"; }

 private:
  SdlGlContext() = default;
  void* window_ = nullptr;   // SDL_Window*
  void* context_ = nullptr;  // SDL_GLContext
  bool video_ = false;
};

}  // namespace psxrl::frontend
