#include "VcdClose.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "common/InputError.hpp"

namespace arp::scm {

void close_vcd_checked(sc_core::sc_trace_file* tf, const std::string& file, const sc_core::sc_time& unit,
                       const std::string& shown) {
  const double units = sc_core::sc_time_stamp() / unit;
  sc_core::sc_close_vcd_trace_file(tf);
  char buf[32];
  std::snprintf(buf, sizeof buf, "\n#%.0f\n", std::floor(units));
  const std::string last = buf;
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  const std::streamoff size = in ? static_cast<std::streamoff>(in.tellg()) : -1;
  std::string tail(last.size(), '\0');
  const bool whole = size >= static_cast<std::streamoff>(last.size()) &&
                     in.seekg(size - static_cast<std::streamoff>(last.size())) && in.read(tail.data(), static_cast<std::streamsize>(tail.size())) &&
                     tail == last;
  if (!whole)
    throw InputError(shown, "", "the waveform was cut short: it does not end at the time it was closed (" + last.substr(1, last.size() - 2) +
                                    "); the file system took only " + std::to_string(std::max<std::streamoff>(size, 0)) +
                                    " bytes of it (full, or over a file-size limit)");
}

}  // namespace arp::scm
