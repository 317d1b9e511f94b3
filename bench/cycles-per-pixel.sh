#!/usr/bin/env bash
# CPU cycles per display pixel of the functional model on one thread.
# Where perf counts cycles: user-space cycles of a run of N frames minus a run
# of 0 frames (the set-up), divided by N x pixels. Where it cannot (a VM
# without hardware counters, "cycles <not supported>"): the frame loop's wall
# time x the core's clock, measured just before and after the loop from chains
# of dependent instructions (bench/CoreClock.hpp, arp_frame_loop prints it).
# Either way the minimum over RUNS tries: on a shared machine a neighbour can
# only add cycles (cache and memory contention, stolen time), never remove them.
# Run after building. Env: FRAMES (200), RUNS (5), METHOD (perf|clock; default:
# perf if it counts cycles here, else clock).
set -euo pipefail
# Paths given relative name files from where the script was started; the defaults, from the repository.
if [ -n "${LOOP:-}" ]; then LOOP=$(realpath -m -- "$LOOP"); fi
cd "$(dirname "$0")/.."
LOOP=${LOOP:-build/bench/arp_frame_loop}
FRAMES=${FRAMES:-200}
RUNS=${RUNS:-5}
PIXELS=614400  # 2 x 640 x 480
if [ -z "${METHOD:-}" ]; then
  METHOD=clock
  if command -v perf >/dev/null && perf stat -x, -e cycles:u true 2>&1 | grep -q '^[0-9]'; then METHOD=perf; fi
fi
perf_cycles() { perf stat -x, -e cycles:u "$LOOP" "$@" 2>&1 >/dev/null | awk -F, '/cycles/ {print $1}'; }
per_pixel() {  # bilinear memories -> cycles per pixel, one try
  if [ "$METHOD" = perf ]; then
    echo "($(perf_cycles "$1" 1 "$2" "$FRAMES") - $(perf_cycles "$1" 1 "$2" 0)) / ($FRAMES * $PIXELS)" | bc -l
  else
    "$LOOP" "$1" 1 "$2" "$FRAMES" | sed -n 's/^cycles per pixel.*: \([0-9.]*\)$/\1/p'
  fi
}
echo "method: $METHOD$([ "$METHOD" = clock ] && echo ", core clock $("$(dirname "$LOOP")/arp_core_clock")")"
printf "%-10s %-8s %-9s %s\n" filter threads memories "cycles/pixel"
for aa in 0 1; do
  for mems in 1 4; do
    best=""
    missed=0
    for _ in $(seq "$RUNS"); do
      c=$(per_pixel $aa $mems)
      # A try without a figure (the clock's two chains disagreed: the core's clock moved during the
      # measurement) is left out; only a row with no figure at all fails.
      if [ -z "$c" ]; then missed=$((missed + 1)); continue; fi
      if [ -z "$best" ] || [ "$(echo "$c < $best" | bc -l)" = 1 ]; then best=$c; fi
    done
    [ -n "$best" ] || { echo "cycles-per-pixel: no figure in $RUNS tries (see $LOOP's output)" >&2; exit 1; }
    [ "$missed" = 0 ] || echo "($missed of $RUNS tries without a figure: the core's clock moved during them)" >&2
    printf "%-10s %-8s %-9s %.1f\n" "$([ $aa = 1 ] && echo bilinear || echo nearest)" 1 $mems "$best"
  done
done
