// Prints the clock the calling core runs at (bench/CoreClock.hpp), for the
// bench scripts that turn wall-clock rates into cycles on a machine without
// hardware counters. Usage: arp_core_clock [--hz]
//   --hz: the figure alone, in Hz, for a script; exit 1 if the two chains disagree.
#include <cstdio>
#include <cstring>

#include "CoreClock.hpp"

int main(int argc, char** argv) {
  const bool bare = argc == 2 && std::strcmp(argv[1], "--hz") == 0;
  if (argc > 2 || (argc == 2 && !bare)) {
    std::fprintf(stderr,
                 "usage: %s [--hz]\n  the core's clock from two chains of dependent instructions "
                 "(adds, multiplies); --hz prints it alone\n",
                 argv[0]);
    return 2;
  }
  const auto c = arp::bench::measure_core_clock();
  if (bare) {
    if (!c || !c->consistent()) {
      std::fprintf(stderr, "arp_core_clock: %s\n", arp::bench::describe(c).c_str());
      return 1;
    }
    std::printf("%.6g\n", c->hz());
    return 0;
  }
  std::printf("%s\n", arp::bench::describe(c).c_str());
  return c && c->consistent() ? 0 : 1;
}
