#include "InputFile.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "InputError.hpp"

namespace arp {

// Refuses what is not a regular file: a FIFO or a device (/dev/zero) would hang or never end.
uint64_t regular_file_size(const std::string& path, const char* what) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError(path, "", errno == ENOENT ? std::string("cannot open the ") + what + ": it does not exist"
                                               : std::string("cannot open the ") + what + ": " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw InputError(path, "", std::string("the ") + what + " must be a regular file");
  return static_cast<uint64_t>(st.st_size);
}

std::string read_input_file(const std::string& path, size_t max_bytes, const char* what) {
  const uint64_t size = regular_file_size(path, what);
  if (size > max_bytes)
    throw InputError(path, "", std::string("the ") + what + " is " + std::to_string(size) + " bytes, more than the " +
                                   std::to_string(max_bytes) + " allowed");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", std::string("cannot open the ") + what);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::unique_ptr<std::istream> open_input_stream(const std::string& path, const char* what) {
  if (path == "-") return std::make_unique<std::istream>(std::cin.rdbuf());
  regular_file_size(path, what);
  auto in = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*in) throw InputError(path, "", std::string("cannot open the ") + what);
  return in;
}

LineReader::LineReader(std::istream& in, std::string source, size_t max_chars)
    : in_(in), source_(std::move(source)), max_(max_chars) {}

bool LineReader::next(std::string& line) {
  line.clear();
  std::streambuf* sb = in_.rdbuf();
  bool any = false;
  for (;;) {
    const int c = sb->sbumpc();
    if (c == std::char_traits<char>::eof()) break;
    any = true;
    if (c == '\n') break;
    if (c == '\0') {
      ++line_;
      throw InputError(source_, where(), "a NUL byte: binary data, not text");
    }
    if (line.size() == max_) {
      ++line_;
      throw InputError(source_, where(), "longer than " + std::to_string(max_) + " characters");
    }
    line.push_back(static_cast<char>(c));
  }
  if (!any) return false;
  ++line_;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return true;
}

std::string trim_blanks(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

}  // namespace arp
