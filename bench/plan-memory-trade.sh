#!/usr/bin/env bash
# The trade a plan makes between display memory and the host's rendering, measured: `arpsim plan` for a
# scene and its walk at one theta_t, held to each display-memory limit in LIMITS (`--memory-limit`, MiB; 0:
# none), then the walk run with each plan and with the hand default (functional level, the host simulated by
# priority, the error against one truth for all: --truth-face-size TRUTH). One row each: the plan's ladder,
# the display memory the configuration describes, the host load the plan predicts over the whole walk and
# the run's over its FRAMES frames, the image error walking, the largest displacement of a tracked point
# against theta_t, and (STILL=1) the error standing at the walk's start and turning at 30 deg/s against an
# area-sampled truth (the error the faces and widths make, without the walk's translation lag).
# Writes OUT/plan-memory-trade.csv, .md and, with gnuplot, .png (memory against load, the error beside).
# Usage: bench/plan-memory-trade.sh SCENE WALK [OUT]   (env: ARPSIM, THETA=8, LIMITS="0 120 90 60 30",
#        FRAMES=120, TRUTH=1024, STILL=1, STILL_TRUTH=2048). Needs jq.
set -euo pipefail
# Paths given relative name files from where the script was started; the defaults, from the repository.
file_or_name() { if [ -e "$1" ]; then realpath -- "$1"; else printf '%s' "$1"; fi; }  # a scene or walk may be a built-in name
SCENE=$(file_or_name "$1") WALK=$(file_or_name "$2") OUT=$(realpath -m -- "${3:-plan-memory-trade}")
if [ -n "${ARPSIM:-}" ]; then ARPSIM=$(realpath -m -- "$ARPSIM"); fi
cd "$(dirname "$0")/.."
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
THETA=${THETA:-8}
LIMITS=${LIMITS:-"0 120 90 60 30"}
FRAMES=${FRAMES:-120}
TRUTH=${TRUTH:-1024}
STILL=${STILL:-1}
STILL_TRUTH=${STILL_TRUTH:-2048}
command -v jq >/dev/null || { echo "plan-memory-trade: needs jq (apt-get install jq)" >&2; exit 1; }
mkdir -p "$OUT"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# A figure from the plan's account (plan.md's Figures table, the plan's column): the row's last cell.
planned() { grep -F "| $1 " "$2" | head -1 | awk -F'|' '{gsub(/ /, "", $(NF-1)); print $(NF-1)}'; }
run_walk() {  # report, config args...
  local report=$1; shift
  "$ARPSIM" run -q "$@" --scene "$SCENE" --walk "$WALK" --threshold-deg "$THETA" --frames "$FRAMES" --every 0 \
    --error-every 10 --truth-face-size "$TRUTH" --report "$report" > /dev/null 2> "$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
}
run_still() {  # report, config args... (a plan is made for the walk: its warning that the motion differs is expected)
  local report=$1; shift
  "$ARPSIM" run -q "$@" --scene "$SCENE" --walk "$WALK" --speed 0 --motion rotate --rate 30 --threshold-deg "$THETA" \
    --frames 121 --every 0 --error-every 20 --truth-face-size "$STILL_TRUTH" --truth-supersample 2 --report "$report" \
    > /dev/null 2> "$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
}
header="limit_mib,memories,update_frames,update_ratio,face_size,display_memory_mib,planned_triangles_per_s,triangles_per_s"
header="$header,mean_psnr_db,worst_psnr_db,max_displacement_deg,worst_share_another_object,texels_lost,still_psnr_db"
echo "$header" > "$tmp/trade.csv"
row() {  # limit, walking report, standing report or "", planned triangles/s or "" -> a CSV row
  jq -r --arg limit "$1" --arg still "$( [ -n "$3" ] && jq '.host.error.mean_psnr_db' "$3" )" --arg planned "$4" \
    '[$limit, .config.memory.count, .config.memory.update_frames, .config.memory.update_ratio, .config.memory.face_size,
      (.footprint.display_memory_bytes_hardware / 1048576 * 10 | round / 10), $planned, (.host.triangles_per_s | round),
      (.host.error.mean_psnr_db * 100 | round / 100), (.host.error.worst_psnr_db * 100 | round / 100),
      (.host.error.max_displacement_deg * 1000 | round / 1000), (.host.error.worst_share_showing_another_object * 10000 | round / 10000),
      (.footprint.texels_lost_on_absent_faces + .footprint.texels_lost_off_tiles + .footprint.texels_lost_tile_pool_full),
      (if $still == "" then "" else ($still | tonumber * 100 | round / 100) end)] | map(tostring) | join(",")' "$2"
}
n=0; total=$(( $(wc -w <<< "$LIMITS") + 1 )); start=$SECONDS
progress() { n=$((n + 1)); local el=$((SECONDS - start)); echo "plan-memory-trade: $n of $total ($1) after ${el} s, about $(( el * (total - n) / n )) s left" >&2; }
run_walk "$tmp/default.json"
still=""; if [ "$STILL" = 1 ]; then run_still "$tmp/default-still.json"; still="$tmp/default-still.json"; fi
row default "$tmp/default.json" "$still" "" >> "$tmp/trade.csv"
progress "the default"
for limit in $LIMITS; do
  "$ARPSIM" plan -q --scene "$SCENE" --walk "$WALK" --threshold-deg "$THETA" --memory-limit "$limit" \
    -o "$tmp/plan-$limit.json" > /dev/null 2> "$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
  run_walk "$tmp/walk-$limit.json" --config "$tmp/plan-$limit.json"
  still=""; if [ "$STILL" = 1 ]; then run_still "$tmp/still-$limit.json" --config "$tmp/plan-$limit.json"; still="$tmp/still-$limit.json"; fi
  row "$limit" "$tmp/walk-$limit.json" "$still" "$(planned 'host load, triangles/s' "$tmp/plan-$limit.md")" >> "$tmp/trade.csv"
  progress "--memory-limit $limit"
done
mv "$tmp/trade.csv" "$OUT/plan-memory-trade.csv"
{
  echo "| --memory-limit MiB | memories | display memory MiB | host triangles/s: planned (whole walk) / run ($FRAMES frames) | mean PSNR dB walking (truth $TRUTH) | worst PSNR dB | largest displacement (theta_t $THETA deg) | worst share of another object | texels lost | PSNR dB standing, turning 30 deg/s (truth $STILL_TRUTH, 2 x 2) |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  tail -n +2 "$OUT/plan-memory-trade.csv" | while IFS=, read -r limit count frames ratio face mib planned tris mean worst disp share lost stillp; do
    [ "$limit" = default ] || [ "$limit" != 0 ] || limit="none"
    printf "| %s | %s every %s x %s^m (face %s) | %s | %s / %s | %s | %s | %s deg | %s | %s | %s |\n" "$limit" "$count" "$frames" "$ratio" \
      "$face" "$mib" "${planned:--}" "$tris" "$mean" "$worst" "$disp" "$share" "$lost" "${stillp:--}"
  done
} > "$OUT/plan-memory-trade.md"
cat "$OUT/plan-memory-trade.md"
echo "written $OUT/plan-memory-trade.csv and .md"
if command -v gnuplot >/dev/null; then
  csv="$OUT/plan-memory-trade.csv"
  gnuplot <<GP
set terminal pngcairo size 900,560 font ",11"
set output "$OUT/plan-memory-trade.png"
set datafile separator ","
set title "$(basename "$SCENE" .json), theta_t $THETA deg: display memory against the host's rendering, each plan held to a limit"
set xlabel "display memory the configuration describes (MiB)"
set ylabel "host triangles rendered per second, run (millions)"
set logscale y
set y2label "mean PSNR walking (dB)"
set y2tics
set ytics nomirror
set key below
set grid
set xrange [0:*]
set offsets 0, 8, 0, 0
plot "$csv" using 6:(strcol(1) ne "default" ? \$8/1e6 : 1/0):(sprintf("%s mem.", strcol(2))) skip 1 with labels offset 0,1 notitle, \
     "$csv" using 6:(strcol(1) ne "default" ? \$8/1e6 : 1/0) skip 1 with points pt 7 ps 1.5 title "plans (host load)", \
     "$csv" using 6:(strcol(1) eq "default" ? \$8/1e6 : 1/0) skip 1 with points pt 5 ps 1.8 title "the hand default (host load)", \
     "$csv" using 6:(strcol(1) ne "default" ? \$9 : 1/0) skip 1 axes x1y2 with points pt 6 ps 1.5 title "plans (PSNR, right axis)", \
     "$csv" using 6:(strcol(1) eq "default" ? \$9 : 1/0) skip 1 axes x1y2 with points pt 4 ps 1.8 title "the default (PSNR, right axis)"
GP
  echo "written $OUT/plan-memory-trade.png"
else
  echo "plan-memory-trade: gnuplot not installed; CSV and table only" >&2
fi
