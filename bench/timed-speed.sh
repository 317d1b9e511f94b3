#!/usr/bin/env bash
# Simulation speed of every fidelity level, in simulated pixel clocks per wall
# second, on the default configuration (stereo 640x480 VGA timing, 4 memories,
# bilinear, per-scanline latch) with the head turning at 200 deg/s: the
# `arpsim run` report's own figure (time inside the simulation only, set-up
# excluded), best of RUNS tries -- on a shared machine a neighbour only ever
# slows a run down. With VCD on, the whole run is traced: every signal
# (--vcd-signals all), or the control signals only (control).
# Also checks that every level produced the same frames and photon times, and
# gives each level's host cycles per simulated pixel clock: the core's clock
# (bench/CoreClock.hpp, measured before and after the level's runs, the faster
# kept: an upper bound on the cycles) times the cores the level runs on (the
# functional level: every core; the others: one) over the rate. Without a
# clock figure (arp_core_clock missing, not x86-64, or its chains disagreeing)
# the column says n/a.
# The functional level runs FUNCTIONAL_FRAMES (64) for its speed: 8 of its
# frames take some 30 ms, where a neighbour's moment moves the figure by tens
# of per cent; its frames are compared from a run of FRAMES like the others.
# The verilated level needs a build with Verilator (scripts/setup.sh).
# Usage: bench/timed-speed.sh [CSV]   (env: FRAMES, FUNCTIONAL_FRAMES, VCD_FRAMES, RUNS, ARPSIM)
set -euo pipefail
# Paths given relative name files from where the script was started; the defaults, from the repository.
if [ -n "${ARPSIM:-}" ]; then ARPSIM=$(realpath -m -- "$ARPSIM"); fi
if [ -n "${1:-}" ]; then set -- "$(realpath -m -- "$1")"; fi
cd "$(dirname "$0")/.."
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
FRAMES=${FRAMES:-8}
FUNCTIONAL_FRAMES=${FUNCTIONAL_FRAMES:-64}
VCD_FRAMES=${VCD_FRAMES:-2}
RUNS=${RUNS:-3}
CSV=${1:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
speed() {  # level frames extra-args... -> best pixel clocks/s; leaves the report in $tmp/last.json
  local level=$1 frames=$2 best=0
  shift 2
  for _ in $(seq "$RUNS"); do
    "$ARPSIM" run -q --fidelity "$level" --frames "$frames" --every 0 --motion rotate --rate 200 \
      --report "$tmp/r.json" "$@" >/dev/null
    s=$(sed -n 's/.*"pixel_clocks_per_second": \([0-9.e+-]*\).*/\1/p' "$tmp/r.json")
    if awk -v a="$s" -v b="$best" 'BEGIN { exit !(a > b) }'; then best=$s; cp "$tmp/r.json" "$tmp/last.json"; fi
  done
  echo "$best"
}
fingerprint() { grep -o '"p[a-z]*_hash": *"[0-9a-f]*"' "$tmp/last.json" | tr '\n' ' '; }
CLOCK=${CLOCK:-$(dirname "$ARPSIM")/../../bench/arp_core_clock}
hz() { "$CLOCK" --hz 2>/dev/null || echo 0; }
echo "level,vcd,frames,pixel_clocks_per_s,core_hz,host_cycles_per_pixel_clock" > "$tmp/out.csv"
printf "%-11s %-8s %-7s %-17s %s\n" level vcd frames "M pixel clocks/s" "host cycles / pixel clock"
ref=""
for level in functional lt cycle detailed verilated; do
  h0=$(hz)
  frames=$FRAMES
  [ "$level" = functional ] && frames=$FUNCTIONAL_FRAMES
  s=$(speed "$level" "$frames")
  h=$(awk -v a="$h0" -v b="$(hz)" 'BEGIN { print (a > b ? a : b) }')
  [ "$frames" = "$FRAMES" ] || RUNS=1 speed "$level" "$FRAMES" > /dev/null  # the frames compared: FRAMES of them
  cores=1
  [ "$level" = functional ] && cores=$(nproc)
  cyc=$(awk -v h="$h" -v s="$s" -v c="$cores" 'BEGIN { if (h > 0) printf "%.0f", h * c / s; else printf "n/a" }')
  fp=$(fingerprint)
  [ -z "$ref" ] && ref=$fp
  same=$([ "$fp" = "$ref" ] && echo "frames and photon times identical to functional" || echo "DIFFERENT FROM FUNCTIONAL")
  printf "%-11s %-8s %-7s %8.2f          %6s at %.2f GHz   %s\n" "$level" off "$frames" "$(awk -v s="$s" 'BEGIN { print s / 1e6 }')" \
    "$cyc" "$(awk -v h="$h" 'BEGIN { print h / 1e9 }')" "$same"
  echo "$level,off,$frames,$s,$h,$cyc" >> "$tmp/out.csv"
  [ "$fp" = "$ref" ] || exit 1
done
for level in lt cycle detailed; do
  for signals in all control; do
    [ "$level" = lt ] && [ "$signals" = control ] && continue  # lt traces its quantum variables only
    s=$(speed "$level" "$VCD_FRAMES" --vcd "$tmp/w.vcd" --vcd-signals "$signals")
    printf "%-11s %-8s %-7s %8.2f   (VCD %s MB)\n" "$level" "$signals" "$VCD_FRAMES" "$(awk -v s="$s" 'BEGIN { print s / 1e6 }')" \
      "$(( $(stat -c %s "$tmp/w.vcd") / 1000000 ))"
    echo "$level,$signals,$VCD_FRAMES,$s,," >> "$tmp/out.csv"
  done
done
[ -n "$CSV" ] && cp "$tmp/out.csv" "$CSV" && echo "written $CSV"
