// Console::use_gl_renderer: the OpenGL renderer put behind the console's face, so that the layers
// above (environments, CLI, Python) choose a renderer without including gpu/gl/.
#include "core/console.h"
#include "gpu/gl/gl_renderer.h"
#include "gpu/gl/osmesa_context.h"

namespace psx {

static_assert(Console::kMaxRenderScale == gpu::gl::kMaxScale);

bool Console::use_gl_renderer(u32 scale, std::string& error) {
  auto r = gpu::gl::make_osmesa_renderer(scale, gpu::gl::OsMesaContext::library_from_environment(), error);
  if (!r) return false;
  set_renderer(std::move(r));
  return true;
}

bool Console::use_gl_renderer(std::unique_ptr<gpu::gl::GlContext> context, u32 scale, std::string& error) {
  auto r = gpu::gl::GlRenderer::create(std::move(context), scale, error);
  if (!r) return false;
  set_renderer(std::move(r));
  return true;
}

}  // namespace psx
