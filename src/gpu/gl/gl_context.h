// Where the OpenGL renderer draws: an OpenGL 3.3 core context it can make current and ask for
// entry points. OSMesa (osmesa_context.h) is the headless one; a window toolkit can supply its
// own. The renderer never draws to the context's default framebuffer, only to its own textures.
#pragma once
#include <string>

namespace psx::gpu::gl {

class GlContext {
 public:
  virtual ~GlContext() = default;
  // Makes this context current on the calling thread if it is not already.
  virtual void make_current() = 0;
  // An entry point of the current context, or null.
  virtual void* proc_address(const char* name) = 0;
  // Human-readable name for messages, e.g. "OSMesa (llvmpipe)".
  virtual std::string name() const = 0;
};

}  // namespace psx::gpu::gl
