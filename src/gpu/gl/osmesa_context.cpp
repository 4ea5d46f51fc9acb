// OSMesa context creation through dlopen (osmesa_context.h). The OSMesa entry points and
// constants are declared here from Mesa's GL/osmesa.h so that building needs no GL library.
#include "gpu/gl/osmesa_context.h"

#include <dlfcn.h>

#include <cstdlib>
#include <type_traits>

namespace psx::gpu::gl {

namespace {
// GL/osmesa.h
constexpr int kOsMesaFormat = 0x22, kOsMesaDepthBits = 0x30, kOsMesaStencilBits = 0x31, kOsMesaAccumBits = 0x32;
constexpr int kOsMesaProfile = 0x33, kOsMesaCoreProfile = 0x34, kOsMesaMajor = 0x36, kOsMesaMinor = 0x37;
constexpr int kGlRgba = 0x1908, kGlUnsignedByte = 0x1401;
}  // namespace

struct OsMesaContext::Api {
  void* (*create_context_attribs)(const int* attribs, void* share) = nullptr;
  void (*destroy_context)(void* ctx) = nullptr;
  unsigned char (*make_current)(void* ctx, void* buffer, unsigned type, int width, int height) = nullptr;
  void* (*get_current_context)() = nullptr;
  void* (*get_proc_address)(const char* name) = nullptr;
};

std::string OsMesaContext::library_from_environment() {
  const char* library = std::getenv("PSXRL_OSMESA_LIBRARY");
  return library && *library ? library : kDefaultLibrary;
}

std::unique_ptr<OsMesaContext> OsMesaContext::create(const std::string& library, std::string& error) {
  std::unique_ptr<OsMesaContext> c(new OsMesaContext());
  c->library_ = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!c->library_) {
    const char* why = dlerror();
    error = why ? std::string(why) : "cannot load " + library;
    return nullptr;
  }
  c->api_ = std::make_unique<Api>();
  Api& a = *c->api_;
  auto bind = [&](auto& fn, const char* name) {
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(c->library_, name));
    if (!fn && error.empty()) error = library + " has no " + name;
  };
  bind(a.create_context_attribs, "OSMesaCreateContextAttribs");
  bind(a.destroy_context, "OSMesaDestroyContext");
  bind(a.make_current, "OSMesaMakeCurrent");
  bind(a.get_current_context, "OSMesaGetCurrentContext");
  bind(a.get_proc_address, "OSMesaGetProcAddress");
  if (!error.empty()) return nullptr;
  const int attribs[] = {kOsMesaFormat, kGlRgba, kOsMesaDepthBits, 0, kOsMesaStencilBits, 0, kOsMesaAccumBits, 0,
                         kOsMesaProfile, kOsMesaCoreProfile, kOsMesaMajor, 3, kOsMesaMinor, 3, 0};
  c->context_ = a.create_context_attribs(attribs, nullptr);
  if (!c->context_) {
    error = "OSMesa could not create an OpenGL 3.3 core context";
    return nullptr;
  }
  if (!a.make_current(c->context_, c->buffer_, kGlUnsignedByte, 4, 4)) {
    error = "OSMesa could not make its context current";
    return nullptr;
  }
  return c;
}

OsMesaContext::~OsMesaContext() {
  if (context_) {
    if (api_->get_current_context() == context_) api_->make_current(nullptr, nullptr, 0, 0, 0);
    api_->destroy_context(context_);
  }
  // libOSMesa stays loaded (no dlclose): Mesa's driver and its LLVM keep process-wide state that
  // is not built to be unloaded, and while it is loaded LeakSanitizer can name the library that
  // holds that state (tests/lsan.supp) instead of an unknown module.
}

void OsMesaContext::make_current() {
  if (api_->get_current_context() != context_) api_->make_current(context_, buffer_, kGlUnsignedByte, 4, 4);
}

void* OsMesaContext::proc_address(const char* name) { return api_->get_proc_address(name); }

}  // namespace psx::gpu::gl
