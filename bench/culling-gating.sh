#!/usr/bin/env bash
# What face culling and clock gating each save, switched on and off side by
# side (issue 14): two markdown tables.
#  - clock gating (--no-clock-gating): a head shake at the cycle and detailed
#    levels, default configuration; speed, pixel and host clocks evaluated, and
#    whether the report (all but its speed section) is identical.
#  - face culling (--no-face-culling): the gallery walk at the functional
#    level, the host rendering by priority with a modelled engine whose cost
#    is below the clock's resolution (1e30 triangles and texels a second), so
#    both runs render the same objects at the same times; the host's wall time
#    per frame, the triangles it submits, and whether every frame is
#    identical. (With any slower engine the unculled one takes longer, so the
#    next memory's render starts later, from a slightly different eye: frames
#    119-120 of this walk differ by 30 pixels at 1e15 a second -- the cost of
#    the extra work, not a culling error.)
# Runs alternate and the best of RUNS is kept. Usage: bench/culling-gating.sh
# (env: ARPSIM, FRAMES=10 (gating), WALK_FRAMES=120 (culling), RUNS=3). Needs jq.
set -euo pipefail
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
FRAMES=${FRAMES:-10} WALK_FRAMES=${WALK_FRAMES:-120} RUNS=${RUNS:-3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
best() {  # name, jq speed expression, arpsim arguments... -> $tmp/NAME.json, the fastest of the tries (higher is better)
  local name=$1 expr=$2; shift 2
  "$ARPSIM" "$@" --report "$tmp/$name.try.json" > /dev/null
  if [ ! -f "$tmp/$name.json" ] || jq -e --slurpfile old "$tmp/$name.json" "($expr) > (\$old[0] | $expr)" "$tmp/$name.try.json" > /dev/null; then
    mv "$tmp/$name.try.json" "$tmp/$name.json"
  fi
}
speed='.simulation.pixel_clocks_per_second'
for _ in $(seq "$RUNS"); do
  for level in cycle detailed; do
    best "$level-gated" "$speed" run -q --fidelity "$level" --frames "$FRAMES" --every 0 --motion shake
    best "$level-ungated" "$speed" run -q --fidelity "$level" --frames "$FRAMES" --every 0 --motion shake --no-clock-gating
  done
done
echo "| level | clock gating | M pixel clocks/s | pixel clocks evaluated / simulated | host clocks evaluated | gated / ungated speed | report identical |"
echo "| --- | --- | --- | --- | --- | --- | --- |"
for level in cycle detailed; do
  same=$([ "$(jq -S 'del(.simulation)' "$tmp/$level-gated.json")" = "$(jq -S 'del(.simulation)' "$tmp/$level-ungated.json")" ] && echo yes || echo NO)
  for g in gated ungated; do
    jq -r --arg l "$level" --arg g "$g" --arg same "$same" --slurpfile un "$tmp/$level-ungated.json" \
      "\"| \(\$l) | \(if \$g == \"gated\" then \"on\" else \"off\" end) | \($speed / 1e4 | round / 100) | \" +
       \"\(.simulation.pixel_clocks_evaluated) / \(.simulation.pixel_clocks) (\(.simulation.pixel_clocks_evaluated / .simulation.pixel_clocks * 1000 | round / 10) %) | \" +
       \"\(.simulation.host_clocks_evaluated) | \(if \$g == \"gated\" then ($speed / (\$un[0] | $speed) * 100 | round / 100 | tostring) + \"x\" else \"\" end) | \(\$same) |\"" \
      "$tmp/$level-$g.json"
  done
done
echo
host='(1000 / .host.host_wall_ms_per_frame)'
for _ in $(seq "$RUNS"); do
  for c in culled unculled; do
    best "$c" "$host" run -q --scene gallery --walk gallery --frames "$WALK_FRAMES" --every 0 --error-every 0 \
      --engine-triangles 1e30 --engine-fill 1e30 --engine-setup 0 $([ "$c" = unculled ] && echo --no-face-culling)
  done
done
frames() { jq -c '[.frames[] | {pixel_hash, photon_hash}]' "$1"; }
same=$([ "$(frames "$tmp/culled.json")" = "$(frames "$tmp/unculled.json")" ] && echo yes || echo NO)
echo "| face culling | host wall ms/frame | host triangles/s submitted (modelled) | culled / unculled: wall, triangles | every frame identical |"
echo "| --- | --- | --- | --- | --- |"
for c in culled unculled; do
  jq -r --arg c "$c" --arg same "$same" --slurpfile un "$tmp/unculled.json" \
    "\"| \(if \$c == \"culled\" then \"on\" else \"off\" end) | \(.host.host_wall_ms_per_frame * 10 | round / 10) | \(.host.triangles_per_s | round) | \" +
     \"\(if \$c == \"culled\" then \"\(.host.host_wall_ms_per_frame / \$un[0].host.host_wall_ms_per_frame * 100 | round / 100), \(.host.triangles_per_s / \$un[0].host.triangles_per_s * 100 | round / 100)\" else \"\" end) | \(\$same) |\"" \
    "$tmp/$c.json"
done
