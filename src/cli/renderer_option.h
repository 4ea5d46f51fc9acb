// --renderer software|gl and --scale for psxrl run and play: which GPU backend draws, and at
// what multiple of the native resolution the OpenGL one draws. The OpenGL renderer runs on
// OSMesa (headless; libOSMesa.so.8 unless PSXRL_OSMESA_LIBRARY names another), or on SDL2's
// OpenGL context (the desktop's driver) when play opens its window.
#pragma once
#include <string>

#include <CLI/CLI.hpp>

#include "core/console.h"

namespace psxrl::cli {

struct RendererArgs {
  std::string renderer = "software";
  int scale = 0;  // 0: not given

  // Adds --renderer, and --scale with `scale_help` unless the command has its own --scale.
  void add_to(CLI::App& app, const char* scale_help);
  // A usage message for bad values, or "".
  std::string check() const;
  // The OpenGL renderer's scale (--scale, default `default_scale`); 1 for software.
  int render_scale(int default_scale) const;
  // Installs the chosen renderer in `console`; false with `error` set when OpenGL is unavailable.
  // With `display`, SDL2's OpenGL is tried first and OSMesa is the fallback.
  bool apply(psx::Console& console, int default_scale, std::string& error, bool display = false) const;
};

}  // namespace psxrl::cli
