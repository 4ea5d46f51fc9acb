// Resolving the OpenGL entry point table (gl_functions.h).
#include "gpu/gl/gl_functions.h"

namespace psx::gpu::gl {

bool GlFunctions::load(GlContext& context, std::string& error) {
#define PSXRL_GL_LOAD(type, fn)                                                    \
  fn = reinterpret_cast<type>(context.proc_address("gl" #fn));                     \
  if (!fn) {                                                                       \
    error = context.name() + " does not provide gl" #fn;                           \
    return false;                                                                  \
  }
  PSXRL_GL_FUNCTIONS(PSXRL_GL_LOAD)
#undef PSXRL_GL_LOAD
  return true;
}

}  // namespace psx::gpu::gl
