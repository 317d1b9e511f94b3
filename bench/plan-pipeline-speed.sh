#!/usr/bin/env bash
# The pipeline's simulation speed with a planned configuration against the hand default, at each fidelity level:
# `arpsim plan` for a scene and its walk, then the same walk run with each at every level of LEVELS (host
# simulated by priority, no truth). A level's pipeline time is the run's wall time less the host's rendering
# (host.host_wall_ms_per_frame: the same work at every level, reported apart as issue 14 asks); its speed is the
# simulated pixel clocks over that. Runs alternate (default, plan, ...) and the fastest of RUNS is kept: a
# neighbour on a shared machine only slows a run. Every level of one configuration must give the same frames and
# photon times (every frame's pixel_hash and photon_hash in the reports), or the script fails.
# Also the SystemC modules each elaborates (footprint.systemc_modules), the pixel clocks it evaluated (clock
# gating skips the blanking), and host cycles per simulated pixel clock at the cycle levels (the core's clock from
# bench/arp_core_clock, measured before and after, the faster kept: an upper bound, as bench/timed-speed.sh).
# Usage: bench/plan-pipeline-speed.sh SCENE WALK [CSV]
#        (env: ARPSIM, THETA=8, PLAN_ARGS: more options for arpsim plan, LEVELS="functional cycle detailed",
#         FRAMES=60, RUNS=2). Needs jq.
set -euo pipefail
SCENE=$1 WALK=$2 CSV=${3:-}
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
THETA=${THETA:-8}
LEVELS=${LEVELS:-functional cycle detailed}
FRAMES=${FRAMES:-60}
RUNS=${RUNS:-2}
CLOCK=${CLOCK:-$(dirname "$ARPSIM")/../../bench/arp_core_clock}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
hz() { "$CLOCK" --hz 2>/dev/null || echo 0; }
# shellcheck disable=SC2086
"$ARPSIM" plan -q --scene "$SCENE" --walk "$WALK" --threshold-deg "$THETA" -o "$tmp/plan.json" ${PLAN_ARGS:-} > /dev/null
pipe_rate() {  # report -> simulated pixel clocks per second of pipeline wall time (host rendering excluded)
  jq '.simulation.pixel_clocks / (.simulation.wall_seconds - .host.host_wall_ms_per_frame * .frames_done / 1000)' "$1"
}
one() {  # level name config-args... -> the fastest report in $tmp/LEVEL-NAME.json
  local level=$1 name=$2
  shift 2
  "$ARPSIM" run -q "$@" --fidelity "$level" --scene "$SCENE" --walk "$WALK" --threshold-deg "$THETA" --frames "$FRAMES" \
    --every 0 --error-every 0 --report "$tmp/try.json" > /dev/null
  local best="$tmp/$level-$name.json"
  if [ ! -f "$best" ] || awk -v a="$(pipe_rate "$tmp/try.json")" -v b="$(pipe_rate "$best")" 'BEGIN { exit !(a > b) }'; then
    mv "$tmp/try.json" "$best"
  fi
}
hashes() { jq -c '[.frames[] | .pixel_hash, .photon_hash] | add' "$1" | cksum | cut -d' ' -f1; }
echo "level,configuration,memories,systemc_modules,pixel_clocks,pixel_clocks_evaluated,pipeline_s,pipeline_pixel_clocks_per_s,core_hz,host_cycles_per_pixel_clock" > "$tmp/out.csv"
echo "| level | configuration | memories | SystemC modules | pixel clocks evaluated / simulated | pipeline s | pipeline M pixel clocks/s | plan / default | host cycles per pixel clock |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
first=""
for level in $LEVELS; do
  h0=$(hz)
  for _ in $(seq "$RUNS"); do
    one "$level" default
    one "$level" plan --config "$tmp/plan.json"
  done
  h=$(awk -v a="$h0" -v b="$(hz)" 'BEGIN { print (a > b ? a : b) }')
  cores=1
  [ "$level" = functional ] && cores=$(nproc)
  d=$(pipe_rate "$tmp/$level-default.json")
  for name in default plan; do
    r="$tmp/$level-$name.json"
    [ -z "$first" ] && first=$level
    if [ "$(hashes "$r")" != "$(hashes "$tmp/$first-$name.json")" ]; then
      echo "$name at $level: frames or photon times differ from $first ($(hashes "$r") against $(hashes "$tmp/$first-$name.json"))" >&2
      exit 1
    fi
    s=$(pipe_rate "$r")
    cyc=$(awk -v h="$h" -v s="$s" -v c="$cores" 'BEGIN { if (h > 0) printf "%.0f", h * c / s; else printf "n/a" }')
    ratio=$([ "$name" = plan ] && awk -v a="$s" -v b="$d" 'BEGIN { printf "%.2fx", a / b }' || echo "")
    jq -r --arg l "$level" --arg n "$name" --arg s "$s" --arg r "$ratio" --arg c "$cyc" \
      '(.simulation.wall_seconds - .host.host_wall_ms_per_frame * .frames_done / 1000) as $p |
       "| \($l) | \($n) | \(.config.memory.count) every \(.config.memory.update_frames) x \(.config.memory.update_ratio)^m, face \(.config.memory.face_size) | " +
       "\(.footprint.systemc_modules) | \(.simulation.pixel_clocks_evaluated // "all") / \(.simulation.pixel_clocks) | \($p * 100 | round / 100) | " +
       "\($s | tonumber / 1e4 | round / 100) | \($r) | \(if $l == "functional" then "\($c) (\("'"$cores"'") cores)" else $c end) |"' "$r"
    jq -r --arg l "$level" --arg n "$name" --arg s "$s" --arg h "$h" --arg c "$cyc" \
      '"\($l),\($n),\(.config.memory.count),\(.footprint.systemc_modules),\(.simulation.pixel_clocks),\(.simulation.pixel_clocks_evaluated // .simulation.pixel_clocks),\(.simulation.wall_seconds - .host.host_wall_ms_per_frame * .frames_done / 1000),\($s),\($h),\($c)"' \
      "$r" >> "$tmp/out.csv"
  done
done
echo "Core clock: $(awk -v h="$h" 'BEGIN { printf "%.2f GHz", h / 1e9 }') (bench/arp_core_clock, the last level's)."
if [ -n "$CSV" ]; then
  cp "$tmp/out.csv" "$CSV.tmp" && mv "$CSV.tmp" "$CSV"
  echo "written $CSV"
fi
