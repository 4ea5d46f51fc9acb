// --renderer and --scale (renderer_option.h).
#include "cli/renderer_option.h"

#include <cstdio>

#include "frontend/sdl_gl_context.h"
#include "gpu/gl/gl_renderer.h"
#include "gpu/gl/osmesa_context.h"

namespace psxrl::cli {

void RendererArgs::add_to(CLI::App& app, const char* scale_help) {
  app.add_option("--renderer", renderer,
                 "GPU renderer: software (default, the exact reference) or gl (OpenGL through OSMesa,\n"
                 "drawn at --scale times the resolution)")
      ->type_name("NAME");
  if (scale_help) app.add_option("--scale", scale, scale_help)->type_name("N");
}

std::string RendererArgs::check() const {
  if (renderer != "software" && renderer != "gl") return "--renderer must be software or gl, not '" + renderer + "'";
  if (scale != 0 && (scale < 1 || scale > static_cast<int>(psx::gpu::gl::kMaxScale)))
    return "--scale must be 1 to " + std::to_string(psx::gpu::gl::kMaxScale);
  return "";
}

int RendererArgs::render_scale(int default_scale) const {
  if (renderer != "gl") return 1;
  return scale ? scale : default_scale;
}

bool RendererArgs::apply(psx::Console& console, int default_scale, std::string& error, bool display) const {
  if (renderer != "gl") return true;
  const auto scale = static_cast<psx::u32>(render_scale(default_scale));
  if (display) {
    std::unique_ptr<psx::gpu::gl::GlRenderer> r;
    if (auto context = frontend::SdlGlContext::create(error))
      r = psx::gpu::gl::GlRenderer::create(std::move(context), scale, error);
    if (r) {
      console.set_renderer(std::move(r));
      return true;
    }
    std::fprintf(stderr, "psxrl: SDL2 OpenGL unusable (%s): drawing with OSMesa\n", error.c_str());
    error.clear();
  }
  auto r = psx::gpu::gl::make_osmesa_renderer(scale, psx::gpu::gl::OsMesaContext::library_from_environment(), error);
  if (!r) {
    error = "--renderer gl: OpenGL is not available: " + error +
            " (install libosmesa6, or use --renderer software)";
    return false;
  }
  console.set_renderer(std::move(r));
  return true;
}

}  // namespace psxrl::cli
