#!/usr/bin/env bash
# CPU cycles per display pixel of the functional model (user space, all
# threads), from perf stat: a run of N frames minus a run of 0 frames (the
# set-up), divided by N x pixels; the minimum over RUNS tries, since on a
# shared machine a neighbour can only add cycles (cache and memory contention),
# never remove them. Needs linux-perf; run after building.
set -euo pipefail
cd "$(dirname "$0")/.."
LOOP=${LOOP:-build/bench/arp_frame_loop}
FRAMES=${FRAMES:-200}
RUNS=${RUNS:-5}
PIXELS=614400  # 2 x 640 x 480
command -v perf >/dev/null || { echo "cycles-per-pixel: needs perf (Debian linux-perf)" >&2; exit 2; }
cycles() { perf stat -x, -e cycles:u "$LOOP" "$@" 2>&1 >/dev/null | awk -F, '/cycles/ {print $1}'; }
printf "%-10s %-8s %-9s %s\n" filter threads memories "cycles/pixel"
for aa in 0 1; do
  for mems in 1 4; do
    base=$(cycles $aa 1 $mems 0)
    best=""
    for _ in $(seq "$RUNS"); do
      c=$(echo "($(cycles $aa 1 $mems "$FRAMES") - $base) / ($FRAMES * $PIXELS)" | bc -l)
      if [ -z "$best" ] || [ "$(echo "$c < $best" | bc -l)" = 1 ]; then best=$c; fi
    done
    printf "%-10s %-8s %-9s %.1f\n" "$([ $aa = 1 ] && echo bilinear || echo nearest)" 1 $mems "$best"
  done
done
