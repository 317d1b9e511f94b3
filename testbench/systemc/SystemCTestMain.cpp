// The SystemC benches' main: SystemC's library calls sc_main, which runs the
// GoogleTest cases. SystemC cannot restart a simulation, so ctest runs each
// case in its own process (gtest_discover_tests); a case simulates once.
#include <gtest/gtest.h>

#include <systemc>

#include <cstdlib>

int sc_main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return sc_core::sc_elab_and_sim(argc, argv);
}
