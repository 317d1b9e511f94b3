// The tests link the sim library, and with it SystemC, whose shared library
// needs an sc_main symbol; GoogleTest owns main, so this one is never called.
#include <cstdio>
#include <cstdlib>

extern "C" int sc_main(int, char**) {  // SystemC declares it with C linkage
  std::fprintf(stderr, "arp_tests: sc_main is not an entry point here\n");
  std::abort();
}
