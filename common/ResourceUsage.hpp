// What this process has used so far, for reports and benches.
#pragma once
#include <cstdint>

namespace arp {

// The largest resident set this process has had (getrusage's ru_maxrss), in bytes.
int64_t peak_resident_bytes();

}  // namespace arp
