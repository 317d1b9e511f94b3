#!/usr/bin/env bash
# The main job on the embedded default: one stereo HMD frame of the built-in
# calibration cube map at the default configuration, written to frame.png.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target arpsim
./build/apps/arpsim/arpsim frame --out frame.png "$@"
