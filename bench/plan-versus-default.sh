#!/usr/bin/env bash
# A planned configuration against the hand default, side by side: `arpsim plan`
# for a scene and its walk, then the same walk run with each (functional level,
# the host simulated by priority, the error against the truth measured), and one
# markdown row each: display memory (the hardware the configuration describes,
# and what the model allocated), the pipeline's simulated speed, the host's
# rendering load, the image error against one truth for both (--truth-face-size TRUTH: the plan's face
# and the default's differ, and each against a truth of its own size would not compare). Runs alternate (default, plan, ...) and the
# best speed of RUNS is kept: a neighbour on a shared machine only slows a run.
# Usage: bench/plan-versus-default.sh SCENE WALK   (env: ARPSIM, FRAMES=120, RUNS=2, THETA=0: --threshold-deg, TRUTH=1024,
#        PLAN_ARGS: more options for arpsim plan). Needs jq.
set -euo pipefail
SCENE=$1 WALK=$2
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
FRAMES=${FRAMES:-120}
RUNS=${RUNS:-2}
THETA=${THETA:-0}
TRUTH=${TRUTH:-1024}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# shellcheck disable=SC2086
"$ARPSIM" plan -q --scene "$SCENE" --walk "$WALK" --threshold-deg "$THETA" -o "$tmp/plan.json" ${PLAN_ARGS:-} > "$tmp/plan.out"
sed -n 's/^| \(memory\.[a-z_, .]*\|datapath\.\*\) | \([^|]*\) |.*/  \1 = \2/p' "$tmp/plan.out"
one() {  # name, config args... -> report in $tmp/NAME.json (best speed of RUNS kept)
  local name=$1; shift
  "$ARPSIM" run -q "$@" --scene "$SCENE" --walk "$WALK" --threshold-deg "$THETA" --frames "$FRAMES" --every 0 \
    --error-every 10 --truth-face-size "$TRUTH" --report "$tmp/run-$name.try.json" > /dev/null
  if [ ! -f "$tmp/run-$name.json" ] || [ "$(jq '.simulation.pixel_clocks_per_second' "$tmp/run-$name.try.json" | cut -d. -f1)" -gt \
                                           "$(jq '.simulation.pixel_clocks_per_second' "$tmp/run-$name.json" | cut -d. -f1)" ]; then
    mv "$tmp/run-$name.try.json" "$tmp/run-$name.json"
  fi
}
for _ in $(seq "$RUNS"); do
  one default
  one plan --config "$tmp/plan.json"
done
echo "| configuration | memories | face | display memory, hardware MiB | modelled peak MiB | host ms/frame (wall) | pipeline M pixel clocks/s (host and truth excluded) | host triangles/s (modelled) | mean PSNR dB (truth at $TRUTH) | worst share of another object |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for name in default plan; do
  jq -r --arg n "$name" '(.simulation.wall_seconds - .host.host_wall_ms_per_frame * .frames_done / 1000 - .host.error.wall_seconds) as $pipe |
    "| \($n) | \(.config.memory.count) every \(.config.memory.update_frames) x \(.config.memory.update_ratio)^m | \(.config.memory.face_size) | " +
    "\(.footprint.display_memory_bytes_hardware / 1048576 * 10 | round / 10) | \(.footprint.display_memory_bytes_peak / 1048576 * 10 | round / 10) | " +
    "\(.host.host_wall_ms_per_frame * 10 | round / 10) | \(.simulation.pixel_clocks / $pipe / 1e4 | round / 100) | \(.host.triangles_per_s | round) | " +
    "\(.host.error.mean_psnr_db * 100 | round / 100) | \(.host.error.worst_share_showing_another_object * 10000 | round / 10000) |"' "$tmp/run-$name.json"
done
