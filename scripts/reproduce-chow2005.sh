#!/usr/bin/env bash
# Chow, Pose & Regan 2005 in form: region priority rendering on the gallery
# along a fixed path through the doorways (scenes/gallery-worst-case-walk.json)
# at 1 m/s, 60 Hz, 4 memories, 4 m regions. Writes OUT/ (default chow2005/):
#   tables.md         Table 1 (update rate per memory), Table 2 (segments
#                     rendered per memory with and without segmentation),
#                     rendering load, cracks and tearing without and with warping,
#                     object-level against region-level priority rendering
#   *.json, *-memories.csv   the reports behind the tables
#   frames-*/         every 60th frame of each run
# Usage: scripts/reproduce-chow2005.sh [OUT]   (env: FRAMES, THETA, ARPSIM)
set -euo pipefail
cd "$(dirname "$0")/.."
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
OUT=${1:-chow2005}
FRAMES=${FRAMES:-300}
THETA=${THETA:-0.75}
mkdir -p "$OUT"
value() { grep "\"$1\":" "$2" | tail -1 | sed 's/.*: \([-0-9.e+a-z"]*\).*/\1/' | tr -d '"'; }
run() {  # name, extra arguments
  local name=$1
  shift
  echo "reproduce-chow2005: $name"
  "$ARPSIM" run -q --scene gallery --walk scenes/gallery-worst-case-walk.json --frames "$FRAMES" --every 60 \
    --error-every 10 --threshold-deg "$THETA" --out-dir "$OUT/frames-$name" --report "$OUT/$name.json" \
    --host-csv "$OUT/$name-memories.csv" "$@" >/dev/null
}
run segmented --regions 4
run warped --regions 4 --warp
run unsegmented --regions 4 --no-segmentation
run objects
col() { awk -F, -v c="$2" -v m="$3" 'NR == m + 2 { print $c }' "$1"; }
{
  echo "# Region priority rendering on the gallery, after Chow, Pose & Regan 2005"
  echo
  echo "Path: scenes/gallery-worst-case-walk.json at 1 m/s for $FRAMES frames (60 Hz), 4 memories, 4 m regions, theta_t = $THETA deg."
  echo
  echo "## Table 1: average update rate of each display memory (regions, segmentation)"
  echo
  echo "| display memory | average update rate (Hz) | paper |"
  echo "| --- | --- | --- |"
  paper1=(60.00 39.25 28.21 16.15)
  for m in 0 1 2 3; do printf "| %d | %.2f | %s |\n" $m "$(col "$OUT/segmented-memories.csv" 4 $m)" "${paper1[$m]}"; done
  echo
  echo "## Table 2: object segments rendered per update of each memory"
  echo
  echo "| display memory | with segmentation | without segmentation | paper with | paper without |"
  echo "| --- | --- | --- | --- | --- |"
  pw=(87 44 20 62); pwo=(160 8 3 42)
  for m in 0 1 2 3; do
    printf "| %d | %.1f | %.1f | %s | %s |\n" $m "$(col "$OUT/segmented-memories.csv" 5 $m)" \
      "$(col "$OUT/unsegmented-memories.csv" 5 $m)" "${pw[$m]}" "${pwo[$m]}"
  done
  echo
  echo "## Rendering load, tearing and error"
  echo
  echo "| run | triangles/s | load reduction vs everything every frame | crack pixels/frame | tear pixels/frame | pixels showing nothing | mean PSNR (dB) | largest warp (px) | host CPU (ms/frame) |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  for r in segmented warped unsegmented objects; do
    f="$OUT/$r.json"
    warp=$(grep -q '"max_warp_displacement_px"' "$f" && awk -v v="$(value max_warp_displacement_px "$f")" 'BEGIN { printf "%.1f", v }' || echo "-")
    printf "| %s | %.2f M | %.2fx | %.1f | %.1f | %.1f | %.2f | %s | %.1f |\n" "$r" \
      "$(awk -v v="$(value triangles_per_s "$f")" 'BEGIN { print v / 1e6 }')" "$(value load_reduction "$f")" \
      "$(value mean_crack_pixels "$f")" "$(value mean_tear_pixels "$f")" "$(value mean_tear_gap_pixels "$f")" "$(value mean_psnr_db "$f")" "$warp" \
      "$(value host_wall_ms_per_frame "$f")"
  done
} > "$OUT/tables.md"
# Their future work: the region size. Load, region swaps, tearing and warp
# distortion over region size x theta_t x walking speed (SWEEP_FRAMES each).
SWEEP_FRAMES=${SWEEP_FRAMES:-90}
if [ "${SWEEP:-1}" = 0 ]; then cat "$OUT/tables.md"; echo "written $OUT/tables.md (no sweep)"; exit 0; fi
echo "region_m,theta_deg,speed_m_s,triangles_per_s,swaps_per_min,tear_pixels,warped_tear_pixels,max_warp_px,mean_psnr_db" > "$OUT/region-sweep.csv"
for size in ${SIZES:-2 4 8}; do
  for th in ${THETAS:-0.5 2}; do
    for sp in ${SPEEDS:-1 2}; do
      for w in "" --warp; do
        "$ARPSIM" run -q --scene gallery --walk scenes/gallery-worst-case-walk.json --speed "$sp" --frames "$SWEEP_FRAMES" \
          --every 0 --error-every 15 --threshold-deg "$th" --regions "$size" --margin "$(awk -v s="$size" 'BEGIN { print s / 8 }')" \
          $w --report "$OUT/sweep.json" >/dev/null
        if [ -z "$w" ]; then
          load=$(value triangles_per_s "$OUT/sweep.json"); swaps=$(value reassignments "$OUT/sweep.json")
          tear=$(value mean_tear_pixels "$OUT/sweep.json"); psnr=$(value mean_psnr_db "$OUT/sweep.json")
        else
          wtear=$(value mean_tear_pixels "$OUT/sweep.json"); wpx=$(value max_warp_displacement_px "$OUT/sweep.json")
        fi
      done
      echo "$size,$th,$sp,$load,$(awk -v n="$swaps" -v f="$SWEEP_FRAMES" 'BEGIN { print n * 3600 / f }'),$tear,$wtear,$wpx,$psnr" >> "$OUT/region-sweep.csv"
      echo "  region $size m, theta_t $th deg, $sp m/s: load $load, tear $tear -> $wtear with warping"
    done
  done
done
rm -f "$OUT/sweep.json"
if command -v gnuplot >/dev/null; then
  gnuplot <<GP
set terminal pngcairo size 1100,480 font ",10"
set output "$OUT/region-sweep.png"
set datafile separator ","
set multiplot layout 1,2 title "Region size on the gallery's worst-case walk (1 and 2 m/s)"
set xlabel "region size (m)"
set logscale x 2
set grid
set key top right
set ylabel "triangles rendered per second (millions)"
plot for [th in "0.5 2"] for [sp in "1 2"] "$OUT/region-sweep.csv" using 1:((\$2 == real(th) && \$3 == real(sp)) ? \$4 / 1e6 : 1/0) skip 1 \
     with linespoints title sprintf("theta_t %s deg, %s m/s", th, sp)
set ylabel "tear pixels per frame (dashed: with warping)"
plot for [th in "0.5 2"] for [sp in "1 2"] "$OUT/region-sweep.csv" using 1:((\$2 == real(th) && \$3 == real(sp)) ? \$6 : 1/0) skip 1 \
     with linespoints title sprintf("theta_t %s, %s m/s", th, sp), \
     for [th in "0.5 2"] for [sp in "1 2"] "$OUT/region-sweep.csv" using 1:((\$2 == real(th) && \$3 == real(sp)) ? \$7 : 1/0) skip 1 \
     with linespoints dt 2 notitle
unset multiplot
GP
  echo "written $OUT/region-sweep.png"
fi
cat "$OUT/tables.md"
echo "written $OUT/tables.md, $OUT/region-sweep.csv"
