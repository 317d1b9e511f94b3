#include "ImageFiles.hpp"

#include <OpenImageIO/imageio.h>
#include <filesystem>
#include <system_error>

#include "common/AtomicFile.hpp"
#include "common/InputError.hpp"

namespace arp::host {

namespace fs = std::filesystem;

RgbImage read_rgb8(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, "", "file does not exist");
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw InputError(path, "", "cannot read as an image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw InputError(path, "header", "image has no pixels");
  if (static_cast<int64_t>(spec.width) * spec.height > (int64_t{1} << 28))
    throw InputError(path, "header", "image larger than 2^28 pixels");
  const int nc = spec.nchannels;
  std::vector<uint8_t> raw(static_cast<size_t>(spec.width) * spec.height * static_cast<size_t>(nc));
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::UINT8, raw.data()))
    throw InputError(path, "pixels", "corrupt or truncated image data: " + in->geterror());
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
