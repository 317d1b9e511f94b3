#include "EglContext.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

namespace arp::host {

namespace {

std::string egl_error(const char* what) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(eglGetError()));
  return std::string("OpenGL through EGL is not available: ") + what + " failed (EGL error " + code + ")";
}

// An environment variable set for the lifetime of the object, then put back as it was: Mesa reads its
// options from the environment, and programs the process starts later must not inherit them.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (!value) return;
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value->c_str(), 1);
    set_ = true;
  }
  ~ScopedEnv() {
    if (!set_) return;
    if (old_) setenv(name_, old_->c_str(), 1);
    else unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
  bool set_ = false;
};

}  // namespace

EglContext::EglContext(const EglOptions& opt) {
  // Mesa reads both while the display is initialised and the context made
  // (a later context with other values re-initialises: the destructor
  // terminates the display).
  const ScopedEnv software("LIBGL_ALWAYS_SOFTWARE", opt.software ? std::optional<std::string>("1") : std::nullopt);
  const ScopedEnv threads("LP_NUM_THREADS", opt.threads >= 0 ? std::optional<std::string>(std::to_string(opt.threads)) : std::nullopt);
  EGLDisplay d = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (d == EGL_NO_DISPLAY) throw GlUnavailable(egl_error("eglGetPlatformDisplay(surfaceless)"));
  EGLint major = 0, minor = 0;
  if (!eglInitialize(d, &major, &minor)) throw GlUnavailable(egl_error("eglInitialize"));
  display_ = d;
  const char* ext = eglQueryString(d, EGL_EXTENSIONS);
  const std::string extensions = ext ? ext : "";
  auto fail = [&](const std::string& m) {
    eglTerminate(d);
    display_ = nullptr;
    return GlUnavailable(m);
  };
  for (const char* need : {"EGL_KHR_surfaceless_context", "EGL_KHR_no_config_context"})
    if (extensions.find(need) == std::string::npos)
      throw fail(std::string("OpenGL through EGL is not available: the display lacks ") + need);
  if (!eglBindAPI(EGL_OPENGL_API)) throw fail(egl_error("eglBindAPI(OpenGL)"));
  const EGLint attrs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                          EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext c = eglCreateContext(d, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attrs);
  if (c == EGL_NO_CONTEXT) throw fail(egl_error("eglCreateContext(OpenGL 3.3 core)"));
  if (!eglMakeCurrent(d, EGL_NO_SURFACE, EGL_NO_SURFACE, c)) {
    const std::string m = egl_error("eglMakeCurrent");
    eglDestroyContext(d, c);
    throw fail(m);
  }
  context_ = c;
  const auto* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  renderer_ = r ? r : "?";
  version_ = v ? v : "?";
}

EglContext::~EglContext() {
  if (!display_) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_) eglDestroyContext(display_, context_);
  eglTerminate(display_);
  eglReleaseThread();
}

}  // namespace arp::host
