#!/usr/bin/env bash
# Builds and runs every test twice: an optimised build (-Werror) and an
# AddressSanitizer + UndefinedBehaviorSanitizer build; then the threaded
# tracker path (the libusb stream against the emulated devices) once more
# under ThreadSanitizer, building only what those tests link. Fails on the
# first error. The release build also verilates the RTL (rtl_model/hdl) and
# runs its benches; it fails if Verilator is missing. The sanitizer builds compile at -O1 with line tables only
# (-g1): the sanitizers' reports keep function, file and line, and the build
# takes less than half the time of -O2 -g (RunCommand.cpp: 16 s against 37 s).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
jobs="$(nproc)"
# Each phase says when it starts (seconds since this script did), so a slow run shows where its time went.
phase() { echo "== $1 == (at ${SECONDS} s)"; }
phase "release build"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DARPSIM_REQUIRE_HDL=ON >/dev/null
cmake --build build -j"$jobs"
phase "release tests"
(cd build && ctest --output-on-failure -j"$jobs")
phase "each unity-built source alone, syntax only (the per-file build of quick edits)"
scripts/check-standalone.sh build
phase "ASan + UBSan build"
sanitizer_flags="-O1 -g1 -DNDEBUG"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$sanitizer_flags" \
  -DARPSIM_SANITIZE=ON -DARPSIM_BUILD_BENCH=OFF >/dev/null
cmake --build build-asan -j"$jobs"
phase "ASan + UBSan tests"
# The release run's test times order the ASan run, longest first (ctest's cost data, by test name): in a clean clone
# it has none, and the slowest tests, started last in declaration order, left a core idle at the end. (An ASan
# tree's own times, from an earlier run, are kept.)
mkdir -p build-asan/Testing/Temporary
[ -e build-asan/Testing/Temporary/CTestCostData.txt ] || cp build/Testing/Temporary/CTestCostData.txt build-asan/Testing/Temporary/ 2>/dev/null || true
# intercept_tls_get_addr=0: GCC 12's sanitizer runtime takes a dynamic TLS block that malloc happens to place
# 16 bytes past a page boundary for a pre-2.25 glibc header and reads a bogus range from it; LeakSanitizer's
# tracer then dies at exit (google/sanitizers#1322; `arpsim frame --frame 10` from a long output path hit it
# every time). Leaks are still checked; only pointers held solely in dlopen'd libraries' TLS go unscanned.
(cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0 \
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j"$jobs")
phase "ThreadSanitizer build (the tracker's threaded path)"
cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$sanitizer_flags" \
  -DARPSIM_SANITIZE_THREAD=ON -DARPSIM_BUILD_BENCH=OFF >/dev/null
cmake --build build-tsan -j"$jobs" --target arp_usb_tests
phase "ThreadSanitizer tests"
(cd build-tsan && TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/../tests/usb/tsan.supp" ctest --output-on-failure --no-tests=error -j"$jobs" -R '^RiftStream\.')
phase "all passed"
