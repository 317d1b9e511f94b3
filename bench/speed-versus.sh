#!/usr/bin/env bash
# Two arpsim builds side by side: for every fidelity level, runs of build A
# and build B interleaved (A, B, A, B, ...), best of RUNS each -- on a shared
# machine a neighbour only ever slows a run down, and interleaving gives both
# the same neighbours. Prints the simulated pixel clocks per second of each
# and the ratio B / A (what bench/timed-speed.sh measures for one build).
# Usage: bench/speed-versus.sh ARPSIM_A ARPSIM_B   (env: FRAMES, RUNS, LEVELS, VCD=1: with a waveform of the whole run)
set -euo pipefail
A=$1 B=$2
FRAMES=${FRAMES:-8}
RUNS=${RUNS:-5}
LEVELS=${LEVELS:-functional lt cycle rtl}  # rtl: the name both builds know for the detailed level
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
one() {  # binary level -> pixel clocks/s
  local vcd=()
  [ "${VCD:-0}" = 1 ] && vcd=(--vcd "$tmp/w.vcd")
  "$1" run -q --fidelity "$2" --frames "$FRAMES" --every 0 --motion rotate --rate 200 --report "$tmp/r.json" "${vcd[@]}" >/dev/null
  sed -n 's/.*"pixel_clocks_per_second": \([0-9.e+-]*\).*/\1/p' "$tmp/r.json"
}
printf "%-11s %14s %14s %8s\n" level "A M clocks/s" "B M clocks/s" "B / A"
for level in $LEVELS; do
  ba=0 bb=0
  for _ in $(seq "$RUNS"); do
    a=$(one "$A" "$level"); b=$(one "$B" "$level")
    ba=$(awk -v x="$a" -v y="$ba" 'BEGIN { print (x > y) ? x : y }')
    bb=$(awk -v x="$b" -v y="$bb" 'BEGIN { print (x > y) ? x : y }')
  done
  awk -v l="$level" -v a="$ba" -v b="$bb" 'BEGIN { printf "%-11s %14.2f %14.2f %8.3f\n", l, a / 1e6, b / 1e6, b / a }'
done
