#include "AtomicFile.hpp"

#include <fstream>

#include <unistd.h>

#include "InputError.hpp"

namespace arp {

namespace fs = std::filesystem;

fs::path temp_path_beside(const std::string& target) {
  const fs::path t(target);
  const fs::path dir = t.has_parent_path() ? t.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(target, "", "folder " + dir.string() + " does not exist");
  return dir / ("." + t.stem().string() + ".tmp-" + std::to_string(::getpid()) + t.extension().string());
}

void commit_temp_file(const fs::path& tmp, const std::string& target) {
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    discard_temp_file(tmp);
    throw InputError(target, "", "cannot move the finished file into place: " + ec.message());
  }
}

void discard_temp_file(const fs::path& tmp) noexcept {
  std::error_code ec;
  fs::remove(tmp, ec);
}

void write_text_atomic(const std::string& path, const std::string& text) {
  const auto tmp = temp_path_beside(path);
  std::ofstream out(tmp, std::ios::binary);
  out << text;
  out.close();
  if (!out) {
    discard_temp_file(tmp);
    throw InputError(path, "", "cannot write the file");
  }
  commit_temp_file(tmp, path);
}

}  // namespace arp
