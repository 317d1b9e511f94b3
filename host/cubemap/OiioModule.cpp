// arpsim's image module: OpenImageIO behind the C interface of OiioModule.hpp.
#include "OiioModule.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace {

void say(char* err, size_t n, const std::string& what) {
  if (err && n) std::snprintf(err, n, "%s", what.c_str());
}

}  // namespace

extern "C" {

void* arp_oiio_open(const char* path, ArpOiioSpec* spec, char* err, size_t err_len) {
  // Only the readers of the formats arpsim documents ever see a file: the one
  // its extension names first, then the others, each asked whether the file's
  // signature is its own. OpenImageIO by itself would go on to try every
  // reader it has (camera raw, DICOM, HEIF, FITS...) on a file none of these
  // recognises: decoders arpsim neither needs nor tests, given untrusted bytes.
  std::unique_ptr<OIIO::ImageInput> in;
  const std::string ext = OIIO::Filesystem::extension(path, false);
  auto named = [&ext](const char* exts) {
    for (const auto& e : OIIO::Strutil::splitsv(exts, ","))
      if (OIIO::Strutil::iequals(e, ext)) return true;
    return false;
  };
  for (int pass = 0; pass < 2 && !in; ++pass)
    for (const ArpImageFormat& f : kArpImageFormats) {
      if (named(f.extensions) != (pass == 0)) continue;  // the extension's own reader first
      auto candidate = OIIO::ImageInput::create(f.oiio_name);
      if (candidate && candidate->valid_file(path)) {
        in = std::move(candidate);
        break;
      }
    }
  if (!in) {  // (an empty reason: ImageFiles names the formats)
    say(err, err_len, "");
    OIIO::geterror();  // clears what the probes left
    return nullptr;
  }
  OIIO::ImageSpec s;
  if (!in->open(path, s)) {
    std::string e = in->geterror();
    say(err, err_len, std::string(in->format_name()) + ": " + (e.empty() ? OIIO::geterror() : e));
    return nullptr;
  }
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

int arp_oiio_can_write(const char* path) {
  const bool ok = OIIO::ImageOutput::create(path) != nullptr;
  if (!ok) (void)OIIO::geterror();  // (cleared: the next write's reason is its own)
  return ok ? 1 : 0;
}

int arp_oiio_write(const char* path, int width, int height, const unsigned char* rgb, char* err, size_t err_len) {
  // Encoded into memory where the writer can, and stored here: OpenImageIO's writers do not report a short
  // write (a full disk, a file-size limit) and would leave a truncated image behind a success. (Declared
  // before the writer, which must not outlive them.)
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    say(err, err_len, OIIO::geterror());
    return 1;
  }
  const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  const bool in_memory = out->supports("ioproxy") && out->set_ioproxy(&memory);
  bool ok = out->open(path, spec) && out->write_image(OIIO::TypeDesc::UINT8, rgb);
  std::string e = ok ? "" : out->geterror();
  ok = out->close() && ok;
  if (!ok) {
    say(err, err_len, e.empty() ? out->geterror() : e);
    return 2;
  }
  if (!in_memory) {
    // A writer that can only write a file (SGI, FITS ...): read back, since it too would not report a short write.
    std::vector<unsigned char> back(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
    auto in = OIIO::ImageInput::open(path);
    const bool whole = in && in->spec().width == width && in->spec().height == height &&
                       in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, back.data());
    if (in) in->close();
    if (whole) return 0;
    say(err, err_len, "the written file does not read back whole (a full disk or a file-size limit?)");
    return 2;
  }
  std::FILE* f = std::fopen(path, "wb");
  if (!f) {
    say(err, err_len, std::strerror(errno));
    return 2;
  }
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() && std::fflush(f) == 0;
  const int write_errno = errno;
  const bool closed = std::fclose(f) == 0;
  if (written && closed) return 0;
  say(err, err_len, std::strerror(written ? errno : write_errno));
  return 2;
}
}
