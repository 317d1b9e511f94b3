// An OpenGL 3.3 core context without a window or a display server: EGL on
// Mesa's surfaceless platform (the GPU's render node when the machine has
// one, llvmpipe otherwise). Current on the constructing thread; rendering goes
// to framebuffer objects. One context at a time per process.
#pragma once
#include <stdexcept>
#include <string>

namespace arp::host {

// EGL or the GL version it needs is missing: the message says which.
class GlUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct EglOptions {
  bool software = false;  // force llvmpipe (LIBGL_ALWAYS_SOFTWARE) even where a GPU exists
  // llvmpipe's rasteriser threads (LP_NUM_THREADS): -1 its default (one per core, beside the calling
  // thread, which transforms and bins); 0 none: everything on the calling thread.
  int threads = -1;
};

class EglContext {
 public:
  explicit EglContext(const EglOptions& opt = {});  // GlUnavailable on failure
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile) Mesa 22.3.6".
  const std::string& renderer() const { return renderer_; }
  const std::string& version() const { return version_; }
  bool is_llvmpipe() const { return renderer_.find("llvmpipe") != std::string::npos; }

 private:
  void* display_ = nullptr;
  void* context_ = nullptr;
  std::string renderer_, version_;
};

}  // namespace arp::host
