#include "AtomicFile.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include <unistd.h>

#include "InputError.hpp"

namespace arp {

namespace fs = std::filesystem;

fs::path temp_path_beside(const std::string& target) {
  const fs::path t(target);
  std::error_code ec;
  // What it names, through links (/dev/stdout is a link to a descriptor): a link to a file is replaced, never
  // followed (see the header); one to anything else is refused as that thing is.
  const fs::file_status st = fs::status(t, ec);
  if (fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st))
    throw InputError(target, "",
                     std::string("is ") +
                         (fs::is_character_file(st) || fs::is_block_file(st) ? "a device"
                          : fs::is_fifo(st)                                  ? "a FIFO"
                          : fs::is_socket(st)                                ? "a socket"
                                                                             : "not a regular file") +
                         ", not a file: arpsim writes an output as a file (a temporary one renamed into place), which "
                         "would replace it");
  const fs::path dir = t.has_parent_path() ? t.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) {
    throw InputError(target, "", fs::exists(dir, ec) ? dir.string() + " is a file, not a folder"
                                                     : "folder " + dir.string() + " does not exist");
  }
  // ".NAME.tmp-PID.EXT", its stem cut so that it is no longer than the longest name a file system takes
  // (255): any name the target may have, its temporary may too.
  const std::string tail = ".tmp-" + std::to_string(::getpid()) + t.extension().string();
  const std::string stem = t.stem().string();
  return dir / ("." + stem.substr(0, std::min(stem.size(), 255 - std::min<size_t>(255, 1 + tail.size()))) + tail);
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

void write_text_file(const fs::path& file, const std::string& text, const std::string& shown) {
  // stdio, not a stream: a full disk or a file-size limit must come back with its reason (errno).
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (!f) throw InputError(shown, "", std::string("cannot write the file: ") + std::strerror(errno));
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0;
  const int err = errno;
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed) throw InputError(shown, "", std::string("cannot write the file: ") + std::strerror(written ? errno : err));
}

void write_through_temp(const std::string& target, const std::function<void(const fs::path&)>& write) {
  const auto tmp = temp_path_beside(target);
  try {
    write(tmp);
  } catch (...) {
    discard_temp_file(tmp);
    throw;
  }
  commit_temp_file(tmp, target);
}

void write_text_atomic(const std::string& path, const std::string& text) {
  write_through_temp(path, [&](const fs::path& tmp) { write_text_file(tmp, text, path); });
}

OutputGroup::~OutputGroup() {
  for (const auto& s : staged_) discard_temp_file(s.first);
}

fs::path OutputGroup::stage(const std::string& target) {
  staged_.emplace_back(temp_path_beside(target), target);
  return staged_.back().first;
}

void OutputGroup::adopt(const fs::path& tmp, const std::string& target) { staged_.emplace_back(tmp, target); }

void OutputGroup::commit() {
  // Renames cannot run out of space: once every file is written, they appear one after the other (a rename
  // that fails midway -- a folder put in the way meanwhile -- leaves the ones before it in place).
  while (!staged_.empty()) {
    const auto s = staged_.front();
    staged_.erase(staged_.begin());
    try {
      commit_temp_file(s.first, s.second);
    } catch (...) {
      for (const auto& rest : staged_) discard_temp_file(rest.first);
      staged_.clear();
      throw;
    }
  }
}

}  // namespace arp
