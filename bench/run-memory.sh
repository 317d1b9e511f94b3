#!/usr/bin/env bash
# Peak resident memory of `arpsim run` against run length: 1 000, 10 000 and
# 100 000 frames of a small display at 60 Hz (stereo 64 x 48, 1 memory of
# 32^2 faces: the display memories are small, so what grows with the run
# shows) with the head shaking (1 kHz synthetic tracker: 1.7 M samples over
# the longest run), per-frame CSV on. The goal: flat within 10 %.
# Peak RSS is GNU time's maximum resident set size. Usage:
#   bench/run-memory.sh [FIDELITY] [CSV]   (env: ARPSIM, FRAMES="1000 10000 100000")
set -euo pipefail
# Paths given relative name files from where the script was started; the defaults, from the repository.
if [ -n "${ARPSIM:-}" ]; then ARPSIM=$(realpath -m -- "$ARPSIM"); fi
CSV=${2:-}
if [ -n "$CSV" ]; then CSV=$(realpath -m -- "$CSV"); fi
cd "$(dirname "$0")/.."
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
FIDELITY=${1:-functional}
FRAMES=${FRAMES:-"1000 10000 100000"}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# 224 x 93 clocks a frame (64 x 48 active): 1.24992 MHz is 60 Hz.
small=(--set display.h_active=64 --set display.v_active=48 --set display.pixel_clock_hz=1249920
       --set memory.count=1 --set memory.face_size=32)
echo "peak resident memory of arpsim run --fidelity $FIDELITY ($(nproc)x $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'))"
printf '%10s %14s %10s %12s\n' frames simulated_s wall_s peak_MB
first=""
rows=()
for n in $FRAMES; do
  /usr/bin/time -f '%M %e' -o "$tmp/time" "$ARPSIM" run -q --fidelity "$FIDELITY" --frames "$n" --every 0 \
    --motion shake --peak 300 --csv "$tmp/frames.csv" "${small[@]}" >/dev/null
  read -r kb wall < "$tmp/time"
  mb=$(awk -v k="$kb" 'BEGIN { printf "%.1f", k / 1024 }')
  printf '%10s %14s %10s %12s\n' "$n" "$(awk -v n="$n" 'BEGIN { printf "%.0f", n / 60 }')" "$wall" "$mb"
  rows+=("$FIDELITY,$n,$wall,$mb")
  [ -n "$first" ] || first=$mb
  last=$mb
done
awk -v a="$first" -v b="$last" 'BEGIN { printf "longest / shortest: %.3f (goal: within 10%%)\n", b / a }'
if [ -n "$CSV" ]; then
  { echo "fidelity,frames,wall_s,peak_rss_mb"; printf '%s\n' "${rows[@]}"; } > "$CSV.tmp" && mv "$CSV.tmp" "$CSV"
fi
