#!/usr/bin/env bash
# Builds and runs every test twice: an optimised build (-Werror) and an
# AddressSanitizer + UndefinedBehaviorSanitizer build; then the threaded
# tracker path (the libusb stream against the emulated devices) once more
# under ThreadSanitizer, building only what those tests link. Fails on the
# first error.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
jobs="$(nproc)"
echo "== release build =="
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$jobs"
(cd build && ctest --output-on-failure -j"$jobs")
echo "== ASan + UBSan build =="
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DARPSIM_SANITIZE=ON -DARPSIM_BUILD_BENCH=OFF >/dev/null
cmake --build build-asan -j"$jobs"
(cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --output-on-failure -j"$jobs")
echo "== ThreadSanitizer build (the tracker's threaded path) =="
cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DARPSIM_SANITIZE_THREAD=ON -DARPSIM_BUILD_BENCH=OFF >/dev/null
cmake --build build-tsan -j"$jobs" --target arp_usb_tests
(cd build-tsan && TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$PWD/../tests/usb/tsan.supp" ctest --output-on-failure --no-tests=error -j"$jobs" -R '^RiftStream\.')
