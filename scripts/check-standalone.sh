#!/usr/bin/env bash
# Each source of the unity-built targets (the tests, the commands, the run library: ARPSIM_UNITY_BUILD) compiled
# alone, syntax only, with its target's own flags: a file that compiles only because an earlier file of its unity
# batch included something, or that clashes with nothing only because it never shares a batch, would break the
# per-file build developers use for quick edits (-DARPSIM_UNITY_BUILD=OFF). Needs a configured unity build folder
# of the Makefile generator (flags.make, Unity/*.cxx). Usage: scripts/check-standalone.sh [BUILD_DIR] (default build).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
jobs="$(nproc)"
found=0
for dir in "$build"/tests/CMakeFiles/arp_tests.dir "$build"/apps/arpsim/CMakeFiles/arp_app.dir "$build"/sim/CMakeFiles/arp_sim.dir; do
  ls "$dir"/Unity/unity_*.cxx > /dev/null 2>&1 || continue
  found=1
  flags=$(sed -n 's/^CXX_\(DEFINES\|INCLUDES\|FLAGS\) = //p' "$dir/flags.make" | tr '\n' ' ')
  # shellcheck disable=SC2016
  sed -n 's/^#include "\(.*\)"$/\1/p' "$dir"/Unity/unity_*.cxx |
    FLAGS="$flags" xargs -P "$jobs" -I{} sh -c 'eval "c++ $FLAGS -fsyntax-only \"\$1\"" || { echo "check-standalone: $1 does not compile alone" >&2; exit 255; }' _ {}
done
[ "$found" = 1 ] || { echo "check-standalone: no unity build in $build (configure with ARPSIM_UNITY_BUILD=ON)" >&2; exit 1; }
echo "check-standalone: every source of the unity-built targets compiles alone"
