#include "ImageFiles.hpp"

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "common/AtomicFile.hpp"
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

}  // namespace

RgbImage read_rgb8(const std::string& path, const std::function<void(int, int)>& check_size) {
  regular_file_size(path, "image");
  const QuietStderr quiet;  // declared before the reader: restored after it is gone (it may print as it closes)
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw InputError(path, "", "cannot read as an image: " + quoted(OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw InputError(path, "header", "image has no pixels");
  // What reading it would take, before anything is allocated: the header decides, not the file's size.
  const uint64_t pixels = static_cast<uint64_t>(spec.width) * static_cast<uint64_t>(spec.height);
  const uint64_t bytes = pixels > kMaxImagePixels ? UINT64_MAX  // (and the product below cannot overflow)
                                                  : pixels * static_cast<uint64_t>(spec.nchannels) * (spec.format.is_floating_point() ? 4 : 1);
  if (pixels > kMaxImagePixels || bytes > kMaxImageBytes)
    throw InputError(path, "header",
                     std::to_string(spec.width) + " x " + std::to_string(spec.height) + " x " + std::to_string(spec.nchannels) +
                         " channels would take " + (bytes == UINT64_MAX ? std::string("too much") : std::to_string(bytes >> 20) + " MB") +
                         "; images are limited to " +
                         std::to_string(kMaxImageBytes >> 20) + " MB and 2^28 pixels");
  if (check_size) check_size(spec.width, spec.height);
  const int nc = spec.nchannels;
  if (spec.format.is_floating_point()) {
    // High dynamic range faces: every value must be a number.
    std::vector<float> f(pixels * static_cast<size_t>(nc));
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, f.data()))
      throw InputError(path, "pixels", "corrupt or truncated image data: " + quoted(in->geterror()));
    for (size_t i = 0; i < f.size(); ++i)
      if (!std::isfinite(f[i]))
        throw InputError(path, "pixel (" + std::to_string(i / static_cast<size_t>(nc) % static_cast<size_t>(spec.width)) + ", " +
                                   std::to_string(i / static_cast<size_t>(nc) / static_cast<size_t>(spec.width)) + ")",
                         "is not a finite number (NaN or infinity)");
  }
  std::vector<uint8_t> raw(static_cast<size_t>(pixels) * static_cast<size_t>(nc));
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::UINT8, raw.data()))
    throw InputError(path, "pixels", "corrupt or truncated image data: " + quoted(in->geterror()));
  in->close();
  RgbImage img(spec.width, spec.height);
  for (size_t i = 0; i < static_cast<size_t>(spec.width) * spec.height; ++i)
    for (int c = 0; c < 3; ++c) img.rgb[i * 3 + static_cast<size_t>(c)] = raw[i * static_cast<size_t>(nc) + static_cast<size_t>(nc >= 3 ? c : 0)];
  return img;
}

void write_rgb8(const std::string& path, const RgbImage& img) {
  const fs::path tmp = temp_path_beside(path);  // keeps the extension: OpenImageIO picks the format by it
  auto out = OIIO::ImageOutput::create(tmp.string());
  if (!out)
    throw InputError(path, "", "no image format for extension '" + fs::path(path).extension().string() + "': " + OIIO::geterror());
  OIIO::ImageSpec spec(img.width, img.height, 3, OIIO::TypeDesc::UINT8);
  bool ok = out->open(tmp.string(), spec) && out->write_image(OIIO::TypeDesc::UINT8, img.rgb.data());
  std::string err = ok ? "" : out->geterror();
  ok = out->close() && ok;
  if (!ok) {
    discard_temp_file(tmp);
    throw InputError(path, "", "cannot write image: " + (err.empty() ? out->geterror() : err));
  }
  commit_temp_file(tmp, path);
}

}  // namespace arp::host
