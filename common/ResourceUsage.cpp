#include "ResourceUsage.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace arp {

int64_t peak_resident_bytes() {
  rusage u{};
  if (getrusage(RUSAGE_SELF, &u) != 0) return 0;
  return static_cast<int64_t>(u.ru_maxrss) * 1024;  // Linux reports kilobytes
}

int64_t available_memory_bytes() {
  int64_t machine = 0;
  {
    std::ifstream in("/proc/meminfo");
    std::string key, unit;
    int64_t kb = 0;
    while (in >> key >> kb) {
      std::getline(in, unit);
      if (key == "MemAvailable:") {
        machine = kb * 1024;
        break;
      }
    }
  }
  // A process limit on the address space (ulimit -v) ends an allocation before the machine runs out: what is left of
  // it, beyond what the process has mapped already.
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    std::ifstream statm("/proc/self/statm");
    int64_t pages = 0;
    statm >> pages;
    const int64_t left = static_cast<int64_t>(as.rlim_cur) - pages * static_cast<int64_t>(sysconf(_SC_PAGESIZE));
    const int64_t limit = left > 0 ? left : 1;  // (1, not 0: 0 reads as "not known")
    return machine > 0 ? std::min(machine, limit) : limit;
  }
  return machine;
}

int64_t current_resident_bytes() {
  std::ifstream in("/proc/self/statm");
  int64_t size = 0, resident = 0;
  if (!(in >> size >> resident)) return 0;
  return resident * static_cast<int64_t>(sysconf(_SC_PAGESIZE));
}

}  // namespace arp
