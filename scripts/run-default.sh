#!/usr/bin/env bash
# The main job on the embedded defaults: a walk through the built-in gallery,
# the host rendering by priority into 4 display memories and the pipeline
# showing it at the default configuration (stereo 640x480 at 60 Hz). Writes,
# into one folder (default gallery-walk/):
#   frames/frame_NNNNNN.png  every 15th HMD frame, both eyes side by side
#   report.json, frames.csv  per-memory update rates and load, error against the truth, latencies
#   theta-sweep.csv/.png     the rendering-load vs image-error trade over theta_t
#   calibration.png          the calibration cube straight ahead (the pipeline's orientation check)
# Extra arguments go to `arpsim run` (e.g. --frames 600, --motion shake --peak 200).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target arpsim
OUT=${OUT:-gallery-walk}
A=./build/apps/arpsim/arpsim
mkdir -p "$OUT"
$A run --scene gallery --walk gallery --frames 180 --every 15 --out-dir "$OUT/frames" \
  --report "$OUT/report.json" --csv "$OUT/frames.csv" "$@"
FRAMES=30 scripts/theta-sweep.sh "$OUT"
$A frame --out "$OUT/calibration.png" >/dev/null
echo "run-default: open $OUT/ (frames/, report.json, frames.csv, theta-sweep.png, calibration.png)"
