#!/usr/bin/env bash
# Detail only where it matters: a walk run at the functional level with
# detailed windows (--detail) against the same walk detailed throughout and
# functional throughout, side by side on one machine. One markdown row each:
# frames detailed, wall time, the host's share (the same rendering work in
# every run, reported apart), the pipeline's share (wall less host) and its
# ratio to the run detailed throughout; then whether every frame (pixels,
# photon times, latencies, underflows) is identical to that run's.
# Usage: bench/detail-windows.sh   (env: ARPSIM, SCENE=gallery, WALK=gallery, FRAMES=600,
#        WINDOWS="100:103 300:303 500:503", MORE: more options for every run, WINDOW_MORE: for the
#        windowed run only, e.g. "--detail-warmup 0"). Needs jq.
set -euo pipefail
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
SCENE=${SCENE:-gallery} WALK=${WALK:-gallery} FRAMES=${FRAMES:-600}
WINDOWS=${WINDOWS:-"100:103 300:303 500:503"}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
detail=()
for w in $WINDOWS; do detail+=(--detail "$w"); done
one() {  # name, options... -> $tmp/NAME.json
  local name=$1; shift
  # shellcheck disable=SC2086
  "$ARPSIM" run -q --scene "$SCENE" --walk "$WALK" --frames "$FRAMES" --every 0 --error-every 0 ${MORE:-} "$@" \
    --report "$tmp/$name.json" > /dev/null
}
one detailed --fidelity detailed
# shellcheck disable=SC2086
one windows "${detail[@]}" ${WINDOW_MORE:-}
one functional
echo "| run | frames detailed | wall s | host s | pipeline s | pipeline time / detailed throughout's | every frame identical to detailed throughout |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
pipe='(.simulation.wall_seconds - .host.host_wall_ms_per_frame * .frames_done / 1000)'
full=$(jq "$pipe" "$tmp/detailed.json")
frames() { jq -c '[.frames[] | {pixel_hash, photon_hash, latency_ps, underflows, late_discarded}]' "$1"; }
for name in detailed windows functional; do
  same=$([ "$(frames "$tmp/$name.json")" = "$(frames "$tmp/detailed.json")" ] && echo yes || echo NO)
  jq -r --arg n "$name" --arg same "$same" --argjson full "$full" "$pipe as \$p |
    \"| \(\$n) | \(if .detail then .detail.frames_detailed elif .fidelity == \"detailed\" then .frames_done else 0 end) | \" +
    \"\(.simulation.wall_seconds * 100 | round / 100) | \(.host.host_wall_ms_per_frame * .frames_done / 10 | round / 100) | \" +
    \"\(\$p * 100 | round / 100) | \(\$p / \$full * 1000 | round / 1000) (1/\(\$full / \$p * 10 | round / 10)) | \(\$same) |\"" \
    "$tmp/$name.json"
done
