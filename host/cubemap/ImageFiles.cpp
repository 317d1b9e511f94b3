#include "ImageFiles.hpp"

#include <dlfcn.h>
#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "ImagePrecheck.hpp"
#include "OiioModule.hpp"
#include "common/AtomicFile.hpp"
#include "common/CompanionFile.hpp"
#include "common/InputError.hpp"
#include "common/InputFile.hpp"

namespace arp::host {

namespace fs = std::filesystem;

namespace {

// The libraries behind OpenImageIO (libpng, libtiff) print their own lines
// about a broken file on stderr; arpsim's one message already carries the
// reason, so while an image is read their output goes nowhere.
class QuietStderr {
 public:
  QuietStderr() : saved_(::dup(STDERR_FILENO)) {
    std::fflush(stderr);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0) {
      ::dup2(null, STDERR_FILENO);
      ::close(null);
    }
  }
  ~QuietStderr() {
    std::fflush(stderr);
    if (saved_ >= 0) {
      ::dup2(saved_, STDERR_FILENO);
      ::close(saved_);
    }
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

 private:
  int saved_;
};

// The image module, loaded on the first image (OiioModule.hpp says why); InputError naming `path`
// when it cannot be.
struct Oiio {
  decltype(&arp_oiio_open) open = nullptr;
  decltype(&arp_oiio_read) read = nullptr;
  decltype(&arp_oiio_close) close = nullptr;
  decltype(&arp_oiio_write) write = nullptr;
  decltype(&arp_oiio_can_write) can_write = nullptr;
  std::string problem;  // why it is not loaded, if it is not
};

const Oiio& oiio(const std::string& path) {
  static const Oiio api = [] {
    Oiio a;
#ifdef ARPSIM_OIIO_MODULE_BUILT
    const std::string where = companion_file("ARPSIM_OIIO_MODULE", "libarp_oiio.so", ARPSIM_OIIO_MODULE_BUILT);
#else
    const std::string where = companion_file("ARPSIM_OIIO_MODULE", "libarp_oiio.so", nullptr);
#endif
    if (where.empty()) {
      a.problem = "arpsim's image module libarp_oiio.so is not beside this program (set ARPSIM_OIIO_MODULE)";
      return a;
    }
    void* h = ::dlopen(where.c_str(), RTLD_NOW | RTLD_LOCAL);  // never closed: images may be read until exit
    if (!h) {
      const char* e = ::dlerror();
      a.problem = "cannot load arpsim's image module " + where + ": " + (e ? e : "unknown reason");
      return a;
    }
    a.open = reinterpret_cast<decltype(a.open)>(::dlsym(h, "arp_oiio_open"));
    a.read = reinterpret_cast<decltype(a.read)>(::dlsym(h, "arp_oiio_read"));
    a.close = reinterpret_cast<decltype(a.close)>(::dlsym(h, "arp_oiio_close"));
    a.write = reinterpret_cast<decltype(a.write)>(::dlsym(h, "arp_oiio_write"));
    a.can_write = reinterpret_cast<decltype(a.can_write)>(::dlsym(h, "arp_oiio_can_write"));
    if (!a.open || !a.read || !a.close || !a.write || !a.can_write) a.problem = where + " is not arpsim's image module (a function is missing)";
    return a;
  }();
  if (!api.problem.empty()) throw InputError(path, "", "cannot read or write images: " + api.problem);
  return api;
}

// An open image of the module, closed when it goes.
class OpenImage {
 public:
  OpenImage(const Oiio& api, void* h) : api_(api), h_(h) {}
  ~OpenImage() { api_.close(h_); }
  OpenImage(const OpenImage&) = delete;
  OpenImage& operator=(const OpenImage&) = delete;
  void* get() const { return h_; }

 private:
  const Oiio& api_;
  void* h_;
};

constexpr size_t kErrorLength = 512;

}  // namespace

RgbImage read_rgb8(const std::string& path, const std::function<void(int, int)>& check_size) {
  precheck_image(path, regular_file_size(path, "image"), kMaxImagePixels);  // before a decoder allocates from the header
  const Oiio& api = oiio(path);
  const QuietStderr quiet;  // declared before the reader: restored after it is gone (it may print as it closes)
  char err[kErrorLength] = "";
  ArpOiioSpec spec{};
  void* handle = api.open(path.c_str(), &spec, err, sizeof err);
  if (!handle && err[0] == '\0') {
    std::string formats;
    for (const ArpImageFormat& f : kArpImageFormats) formats += (formats.empty() ? "" : ", ") + std::string(f.title);
    throw InputError(path, "", "not an image of a format arpsim reads (" + formats + ")");
  }
  if (!handle) throw InputError(path, "", "cannot read as an image: " + quoted(err));
  const OpenImage in(api, handle);
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw InputError(path, "header", "image has no pixels");
  // What reading it would take, before anything is allocated: the header decides, not the file's size.
  const uint64_t pixels = static_cast<uint64_t>(spec.width) * static_cast<uint64_t>(spec.height);
  const uint64_t bytes = pixels > kMaxImagePixels ? UINT64_MAX  // (and the product below cannot overflow)
                                                  : pixels * static_cast<uint64_t>(spec.nchannels) * (spec.is_float ? 4 : 1);
  if (pixels > kMaxImagePixels || bytes > kMaxImageBytes)
    throw InputError(path, "header",
                     std::to_string(spec.width) + " x " + std::to_string(spec.height) + " x " + std::to_string(spec.nchannels) +
                         " channels would take " + (bytes == UINT64_MAX ? std::string("too much") : std::to_string(bytes >> 20) + " MB") +
                         "; images are limited to " +
                         std::to_string(kMaxImageBytes >> 20) + " MB and 2^28 pixels");
  if (check_size) check_size(spec.width, spec.height);
  const int nc = spec.nchannels;
  if (spec.is_float) {
    // High dynamic range faces: every value must be a number.
    std::vector<float> f(pixels * static_cast<size_t>(nc));
    if (!api.read(in.get(), 1, f.data(), err, sizeof err))
      throw InputError(path, "pixels", "corrupt or truncated image data: " + quoted(err));
    for (size_t i = 0; i < f.size(); ++i)
      if (!std::isfinite(f[i]))
        throw InputError(path, "pixel (" + std::to_string(i / static_cast<size_t>(nc) % static_cast<size_t>(spec.width)) + ", " +
                                   std::to_string(i / static_cast<size_t>(nc) / static_cast<size_t>(spec.width)) + ")",
                         "is not a finite number (NaN or infinity)");
  }
  std::vector<uint8_t> raw(static_cast<size_t>(pixels) * static_cast<size_t>(nc));
  if (!api.read(in.get(), 0, raw.data(), err, sizeof err))
    throw InputError(path, "pixels", "corrupt or truncated image data: " + quoted(err));
  RgbImage img(spec.width, spec.height);
  for (size_t i = 0; i < static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height); ++i)
    for (int c = 0; c < 3; ++c) img.rgb[i * 3 + static_cast<size_t>(c)] = raw[i * static_cast<size_t>(nc) + static_cast<size_t>(nc >= 3 ? c : 0)];
  return img;
}

namespace {

std::string no_format(const std::string& path) {
  return "no image format for extension '" + fs::path(path).extension().string() +
         "' (OpenImageIO has no writer for it: .png, .exr, .tif, .jpg ...)";
}

}  // namespace

void check_image_output(const std::string& option, const std::string& path) {
  if (path.empty()) return;
  if (!oiio(path).can_write(path.c_str())) throw InputError(option, path, no_format(path));
}

void write_rgb8_file(const fs::path& file, const RgbImage& img, const std::string& shown) {
  const Oiio& api = oiio(shown);
  char err[kErrorLength] = "";
  const int rc = api.write(file.string().c_str(), img.width, img.height, img.rgb.data(), err, sizeof err);
  if (rc == 1) throw InputError(shown, "", no_format(shown));  // (err names the temporary file, not the user's)
  if (rc != 0) throw InputError(shown, "", "cannot write image: " + std::string(err));
}

void write_rgb8(const std::string& path, const RgbImage& img) {
  // (the temporary keeps the extension: OpenImageIO picks the format by it)
  write_through_temp(path, [&](const fs::path& tmp) { write_rgb8_file(tmp, img, path); });
}

}  // namespace arp::host
