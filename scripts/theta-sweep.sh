#!/usr/bin/env bash
# The priority-rendering trade: rendering load against image error as the
# threshold angle theta_t grows, over the gallery walk. One `arpsim run` per
# theta_t and memory ladder (RATIOS: memory.update_ratio, memory m updated
# every RATIO^m frames); writes OUT/theta-sweep.csv and, with gnuplot,
# OUT/theta-sweep.png (the first ratio's curve, and the others' loads).
# Usage: scripts/theta-sweep.sh [OUT]   (env: FRAMES, THETAS, RATIOS, ERROR_EVERY, ARPSIM)
set -euo pipefail
cd "$(dirname "$0")/.."
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
OUT=${1:-theta-sweep}
FRAMES=${FRAMES:-45}
THETAS=${THETAS:-"0.25 0.5 1 2 4 8"}
RATIOS=${RATIOS:-2}
ERROR_EVERY=${ERROR_EVERY:-5}
mkdir -p "$OUT"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The last occurrence of a key in arpsim's report (the host summary sorts after the frames).
value() { grep -E "^ *\"$1\":" "$2" | tail -1 | sed 's/.*: \([-0-9.e+]*\).*/\1/'; }
csv="$OUT/theta-sweep.csv"
echo "update_ratio,theta_deg,triangles_per_s,full_render_triangles_per_s,load_reduction,mean_psnr_db,worst_psnr_db,max_displacement_px,max_displacement_deg,worst_share_another_object,object_moves" > "$tmp/sweep.csv"
for ratio in $RATIOS; do
  for th in $THETAS; do
    "$ARPSIM" run -q --scene gallery --walk gallery --frames "$FRAMES" --every 0 --error-every "$ERROR_EVERY" \
      --threshold-deg "$th" --set memory.update_ratio="$ratio" --report "$tmp/r.json" >/dev/null 2>"$tmp/err" || { cat "$tmp/err" >&2; exit 1; }
    row="$ratio,$th,$(value triangles_per_s "$tmp/r.json"),$(value full_render_every_frame_triangles_per_s "$tmp/r.json")"
    row="$row,$(value load_reduction "$tmp/r.json"),$(value mean_psnr_db "$tmp/r.json"),$(value worst_psnr_db "$tmp/r.json")"
    row="$row,$(value max_displacement_px "$tmp/r.json"),$(value max_displacement_deg "$tmp/r.json")"
    row="$row,$(value worst_share_showing_another_object "$tmp/r.json"),$(value object_moves "$tmp/r.json")"
    echo "$row" >> "$tmp/sweep.csv"
    echo "ratio $ratio, theta_t $th deg: $row"
  done
done
mv "$tmp/sweep.csv" "$csv"
echo "written $csv"
if command -v gnuplot >/dev/null; then
  first=${RATIOS%% *}
  gnuplot <<GP
set terminal pngcairo size 900,560 font ",11"
set output "$OUT/theta-sweep.png"
set datafile separator ","
set title "Priority rendering on the gallery walk: rendering load against image error"
set xlabel "threshold angle theta_t (degrees)"
set logscale x 2
set ylabel "triangles rendered per second (millions)"
set y2label "PSNR against the truth (dB)"
set ytics nomirror
set y2tics
set key below
set grid
plot "$csv" using 2:(\$1 == $first ? \$3/1e6 : 1/0) skip 1 with linespoints lw 2 title "priority rendering load (memory m every $first^m frames)", \
     "$csv" using 2:(\$1 == $first ? \$4/1e6 : 1/0) skip 1 with lines dt 2 lw 2 title "everything every frame", \
     "$csv" using 2:(\$1 == $first ? \$6 : 1/0) skip 1 axes x1y2 with linespoints lw 2 title "mean PSNR (right axis)"$(
  for r in $RATIOS; do [ "$r" = "$first" ] || printf ', \\\n     "%s" using 2:($1 == %s ? $3/1e6 : 1/0) skip 1 with linespoints lw 2 title "load, memory m every %s^m frames"' "$csv" "$r" "$r"; done)
GP
  echo "written $OUT/theta-sweep.png"
else
  echo "theta-sweep: gnuplot not installed; CSV only" >&2
fi
