// Reading what users hand arpsim (configurations, scenes, walks, traces,
// datasets, waveforms) so that no file can hang or exhaust it: only regular
// files (or "-", standard input, where a command streams), sizes bounded
// before reading, lines bounded in length, binary data (a NUL byte) refused.
// Every refusal is an InputError naming the file and, for lines, the line.
#pragma once
#include <cstddef>
#include <cstdint>
#include <istream>
#include <memory>
#include <string>

namespace arp {

// The size of a regular file (InputError: missing, or a FIFO, a device, a folder...).
uint64_t regular_file_size(const std::string& path, const char* what);

// A whole regular file, at most max_bytes (InputError: missing, not a regular file, too large).
std::string read_input_file(const std::string& path, size_t max_bytes, const char* what);

// A regular file opened for streaming, or standard input for "-".
std::unique_ptr<std::istream> open_input_stream(const std::string& path, const char* what);

// Lines of a text stream, one at a time: never a line longer than max_chars
// held, never a NUL byte passed on (both InputError naming the line).
class LineReader {
 public:
  static constexpr size_t kDefaultMaxChars = 1 << 16;
  LineReader(std::istream& in, std::string source, size_t max_chars = kDefaultMaxChars);
  // The next line without its end ("\n" or "\r\n"); false at the end of the stream.
  bool next(std::string& line);
  size_t line_number() const { return line_; }
  std::string where() const { return "line " + std::to_string(line_); }
  const std::string& source() const { return source_; }

 private:
  std::istream& in_;
  std::string source_;
  size_t max_;
  size_t line_ = 0;
};

// s without the spaces, tabs and carriage returns at either end (a line's or a field's).
std::string trim_blanks(const std::string& s);

}  // namespace arp
