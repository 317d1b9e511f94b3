// What this process has used so far, for reports and benches.
#pragma once
#include <cstdint>

namespace arp {

// The largest resident set this process has had (getrusage's ru_maxrss), in bytes.
int64_t peak_resident_bytes();
// The resident set now (/proc/self/statm), in bytes; 0 where it cannot be read.
int64_t current_resident_bytes();
// The memory the machine can give without swapping (/proc/meminfo's MemAvailable), or less where the process's
// address-space limit (RLIMIT_AS) leaves less, in bytes; 0 where neither can be read.
int64_t available_memory_bytes();

}  // namespace arp
