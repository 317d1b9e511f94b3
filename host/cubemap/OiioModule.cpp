// arpsim's image module: OpenImageIO behind the C interface of OiioModule.hpp.
#include "OiioModule.hpp"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <memory>
#include <string>

namespace {

void say(char* err, size_t n, const std::string& what) {
  if (err && n) std::snprintf(err, n, "%s", what.c_str());
}

}  // namespace

extern "C" {

void* arp_oiio_open(const char* path, ArpOiioSpec* spec, char* err, size_t err_len) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    say(err, err_len, OIIO::geterror());
    return nullptr;
  }
  const OIIO::ImageSpec& s = in->spec();
  *spec = ArpOiioSpec{s.width, s.height, s.nchannels, s.format.is_floating_point() ? 1 : 0};
  return in.release();
}

int arp_oiio_read(void* image, int as_float, void* pixels, char* err, size_t err_len) {
  auto* in = static_cast<OIIO::ImageInput*>(image);
  const int nc = in->spec().nchannels;
  if (in->read_image(0, 0, 0, nc, as_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8, pixels)) return 1;
  say(err, err_len, in->geterror());
  return 0;
}

void arp_oiio_close(void* image) {
  std::unique_ptr<OIIO::ImageInput> in(static_cast<OIIO::ImageInput*>(image));
  in->close();
}

int arp_oiio_write(const char* path, int width, int height, const unsigned char* rgb, char* err, size_t err_len) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    say(err, err_len, OIIO::geterror());
    return 1;
  }
  const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  bool ok = out->open(path, spec) && out->write_image(OIIO::TypeDesc::UINT8, rgb);
  std::string e = ok ? "" : out->geterror();
  ok = out->close() && ok;
  if (ok) return 0;
  say(err, err_len, e.empty() ? out->geterror() : e);
  return 2;
}
}
