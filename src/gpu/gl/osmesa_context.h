// A headless OpenGL 3.3 core context from Mesa's off-screen library (libOSMesa), loaded with
// dlopen at run time so that psxrl starts, and the software renderer works, on a machine without
// it. No display or window system is involved.
#pragma once
#include <memory>
#include <string>

#include "gpu/gl/gl_context.h"

namespace psx::gpu::gl {

class OsMesaContext final : public GlContext {
 public:
  // The Debian package libosmesa6 installs this soname.
  static constexpr const char* kDefaultLibrary = "libOSMesa.so.8";

  // PSXRL_OSMESA_LIBRARY when set (another Mesa build, or a missing file to test the fallback),
  // else kDefaultLibrary.
  static std::string library_from_environment();

  // Loads `library` and creates a 3.3 core context; null with `error` set when either fails.
  static std::unique_ptr<OsMesaContext> create(const std::string& library, std::string& error);
  ~OsMesaContext() override;

  void make_current() override;
  void* proc_address(const char* name) override;
  std::string name() const override { return "OSMesa"; }

 private:
  OsMesaContext() = default;
  struct Api;
  void* library_ = nullptr;
  std::unique_ptr<Api> api_;
  void* context_ = nullptr;
  // OSMesa needs a colour buffer to make a context current even when all drawing goes to
  // framebuffer objects; this small one is never drawn to.
  unsigned char buffer_[4 * 4 * 4] = {};
};

}  // namespace psx::gpu::gl
