#!/usr/bin/env bash
# A plan made for the head's own motion against one made for the walk alone: `arpsim plan` for a scene and walk
# without and with MOTION (the options `run` takes: --motion ..., --trace FILE), then each configuration and the
# default run over the walk with that head motion (functional level, the host simulated by priority, the error
# against the truth every ERROR_EVERY frames). One markdown row each: the ladder, the hardware display memory, the
# host's rendering load, the image error (mean PSNR, worst frame, the largest displacement of a tracked point
# against theta_t) and the object-frames the plan's memory.assignment held away from the rule's choice.
# Usage: bench/plan-head-motion.sh   (env: ARPSIM, SCENE=gallery, WALK=gallery, SPEED=0 (standing at the walk's
#        first point), MOTION="--motion rotate --rate 300", THETA=2, FRAMES=60, ERROR_EVERY=5, TRUTH=1024). Needs jq.
set -euo pipefail
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
SCENE=${SCENE:-gallery} WALK=${WALK:-gallery} SPEED=${SPEED:-0}
MOTION=${MOTION:-"--motion rotate --rate 300"}
THETA=${THETA:-2} FRAMES=${FRAMES:-60} ERROR_EVERY=${ERROR_EVERY:-5} TRUTH=${TRUTH:-1024}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
walk=(--scene "$SCENE" --walk "$WALK" --speed "$SPEED" --threshold-deg "$THETA")
"$ARPSIM" plan -q "${walk[@]}" -o "$tmp/walk-only.json" > /dev/null
# shellcheck disable=SC2086
"$ARPSIM" plan -q "${walk[@]}" $MOTION -o "$tmp/with-motion.json" > /dev/null
run() {  # name, config args...
  local name=$1; shift
  # shellcheck disable=SC2086
  "$ARPSIM" run -q "$@" "${walk[@]}" $MOTION --frames "$FRAMES" --every 0 --error-every "$ERROR_EVERY" \
    --truth-face-size "$TRUTH" --report "$tmp/run-$name.json" > /dev/null
}
run default
run walk-only --config "$tmp/walk-only.json"
run with-motion --config "$tmp/with-motion.json"
echo "Scene $SCENE, walk $WALK at $SPEED m/s, head motion: $MOTION, theta_t $THETA deg, $FRAMES frames (error every $ERROR_EVERY, truth at $TRUTH)"
echo
echo "| configuration | memories | display memory, hardware MiB | host triangles/s (modelled) | mean PSNR dB | worst PSNR dB | largest displacement deg | object-frames held (slower, faster) |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for name in default walk-only with-motion; do
  jq -r --arg n "$name" '"| \($n) | \(.config.memory.count) every \(.config.memory.update_frames) x \(.config.memory.update_ratio)^m | " +
    "\(.footprint.display_memory_bytes_hardware / 1048576 * 10 | round / 10) | \(.host.triangles_per_s | round) | " +
    "\(.host.error.mean_psnr_db * 100 | round / 100) | \(.host.error.worst_psnr_db * 100 | round / 100) | " +
    "\(.host.error.max_displacement_deg * 1000 | round / 1000) | " +
    "\(.host.object_frames_held_slower_by_assignment), \(.host.object_frames_held_faster_by_assignment) |"' "$tmp/run-$name.json"
done
