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
#   tear-segmented.png, tear-warped.png   a magnified tear (8x): the window
#                     with the most crack pixels, then the same place with warping
#   region-sweep.csv/.png  region size x theta_t x walking speed (their future work)
# Usage: scripts/reproduce-chow2005.sh [OUT]   (env: FRAMES, THETA, ARPSIM)
set -euo pipefail
cd "$(dirname "$0")/.."
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
OUT=${1:-chow2005}
FRAMES=${FRAMES:-300}
THETA=${THETA:-0.75}
mkdir -p "$OUT"
value() { grep -E "^ *\"$1\":" "$2" | tail -1 | sed 's/.*: \([-0-9.e+a-z"]*\).*/\1/' | tr -d '"'; }
run() {  # name, extra arguments
  local name=$1
  shift
  echo "reproduce-chow2005: $name"
  "$ARPSIM" run --scene gallery --walk scenes/gallery-worst-case-walk.json --frames "$FRAMES" --every 60 \
    --error-every 10 --threshold-deg "$THETA" --out-dir "$OUT/frames-$name" --report "$OUT/$name.json" \
    --host-csv "$OUT/$name-memories.csv" "$@" > "$OUT/$name.log"
}
run segmented --regions 4 --tear-image "$OUT/tear-segmented.png"
# The same place with warping.
place=$(grep -o -- '--tear-at [0-9:]*' "$OUT/segmented.log" | cut -d' ' -f2)
run warped --regions 4 --warp --tear-image "$OUT/tear-warped.png" --tear-at "$place"
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
  echo
  echo "Magnified tear (8x; displayed | truth | cracks magenta, tears yellow, seams cyan): tear-segmented.png, and the"
  echo "same place with warping: tear-warped.png (frame:eye:x:y = $place)."
} > "$OUT/tables.md"
# Their future work: the region size. Load, region swaps, tearing and warp
# distortion over region size x theta_t x walking speed (SWEEP_FRAMES each).
SWEEP_FRAMES=${SWEEP_FRAMES:-240}
if [ "${SWEEP:-1}" = 0 ]; then cat "$OUT/tables.md"; echo "written $OUT/tables.md (no sweep)"; exit 0; fi
echo "region_m,theta_deg,speed_m_s,triangles_per_s,swaps_per_min,crack_pixels,warped_crack_pixels,tear_pixels,warped_tear_pixels,max_warp_px,mean_psnr_db,warped_mean_psnr_db" > "$OUT/region-sweep.csv"
set -- ${SIZES:-2 4 8}
sizes=("$@")
thetas=(${THETAS:-0.5 2})
speeds=(${SPEEDS:-1 2})
total=$(( ${#sizes[@]} * ${#thetas[@]} * ${#speeds[@]} ))
n=0
t0=$(date +%s)
for size in "${sizes[@]}"; do
  for th in "${thetas[@]}"; do
    for sp in "${speeds[@]}"; do
      for w in "" --warp; do
        "$ARPSIM" run -q --scene gallery --walk scenes/gallery-worst-case-walk.json --speed "$sp" --frames "$SWEEP_FRAMES" \
          --every 0 --error-every 15 --threshold-deg "$th" --regions "$size" --margin "$(awk -v s="$size" 'BEGIN { print s / 8 }')" \
          $w --report "$OUT/sweep.json" >/dev/null
        if [ -z "$w" ]; then
          load=$(value triangles_per_s "$OUT/sweep.json"); swaps=$(value reassignments "$OUT/sweep.json")
          crack=$(value mean_crack_pixels "$OUT/sweep.json"); tear=$(value mean_tear_pixels "$OUT/sweep.json")
          psnr=$(value mean_psnr_db "$OUT/sweep.json")
        else
          wcrack=$(value mean_crack_pixels "$OUT/sweep.json"); wtear=$(value mean_tear_pixels "$OUT/sweep.json")
          wpx=$(value max_warp_displacement_px "$OUT/sweep.json"); wpsnr=$(value mean_psnr_db "$OUT/sweep.json")
        fi
      done
      echo "$size,$th,$sp,$load,$(awk -v n="$swaps" -v f="$SWEEP_FRAMES" 'BEGIN { print n * 3600 / f }'),$crack,$wcrack,$tear,$wtear,$wpx,$psnr,$wpsnr" >> "$OUT/region-sweep.csv"
      n=$((n + 1))
      el=$(( $(date +%s) - t0 ))
      printf "  [%d/%d, ETA %ds] region %s m, theta_t %s deg, %s m/s: %.2f M tri/s, cracks %.1f -> %.1f px/frame with warping (warp up to %.1f px)\n" \
        "$n" "$total" $(( el * (total - n) / n )) "$size" "$th" "$sp" "$(awk -v v="$load" 'BEGIN { print v / 1e6 }')" "$crack" "$wcrack" "$wpx"
    done
  done
done
rm -f "$OUT/sweep.json"
if command -v gnuplot >/dev/null; then
  # One series per theta_t and speed, through awk so each is a line.
  series() { echo "< awk -F, 'NR > 1 && \$2 == $1 && \$3 == $2' '$OUT/region-sweep.csv' | sort -t, -k1,1g"; }
  plots() {  # y expression, dashed y expression or ""
    local k=0 th sp
    for th in "${thetas[@]}"; do
      for sp in "${speeds[@]}"; do
        [ $k = 0 ] || printf ", "
        k=$((k + 1))
        printf '"%s" using 1:(%s) with linespoints lw 2 lc %d title "theta_t %s deg, %s m/s"' "$(series "$th" "$sp")" "$1" $k "$th" "$sp"
        [ -z "$2" ] || printf ', "%s" using 1:(%s) with linespoints dt 2 lw 2 lc %d notitle' "$(series "$th" "$sp")" "$2" $k
      done
    done
  }
  gnuplot <<GP
set terminal pngcairo size 1200,900 font ",10"
set output "$OUT/region-sweep.png"
set datafile separator ","
set multiplot layout 2,2 title "Region size on the gallery's worst-case walk ($SWEEP_FRAMES frames per point)"
set xlabel "region size (m)"
set logscale x 2
set grid
set key top right
set ylabel "triangles rendered per second (millions)"
plot $(plots '$4 / 1e6' '')
set ylabel "region re-assignments per minute"
plot $(plots '$5' '')
set ylabel "crack pixels per frame (dashed: with warping)"
plot $(plots '$6' '$7')
set ylabel "warping's largest vertex displacement (px)"
plot $(plots '$10' '')
unset multiplot
GP
  echo "written $OUT/region-sweep.png"
fi
cat "$OUT/tables.md"
echo "written $OUT/tables.md, $OUT/region-sweep.csv"
