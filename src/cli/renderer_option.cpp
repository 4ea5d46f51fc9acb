// --renderer and --scale (renderer_option.h).
#include "cli/renderer_option.h"

#include <cstdio>

#include "frontend/sdl_gl_context.h"

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
  if (scale != 0 && (scale < 1 || scale > static_cast<int>(psx::Console::kMaxRenderScale)))
    return "--scale must be 1 to " + std::to_string(psx::Console::kMaxRenderScale);
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
    auto context = frontend::SdlGlContext::create(error);
    if (context && console.use_gl_renderer(std::move(context), scale, error)) return true;
    std::fprintf(stderr, "psxrl: SDL2 OpenGL unusable (%s): drawing with OSMesa\n", error.c_str());
    error.clear();
  }
  if (console.use_gl_renderer(scale, error)) return true;
  error = "--renderer gl: OpenGL is not available: " + error + " (install libosmesa6, or use --renderer software)";
  return false;
}

}  // namespace psxrl::cli
