#!/usr/bin/env bash
# Chow, Pose & Regan 2005 in form: region priority rendering on the gallery
# along a fixed path through the doorways (scenes/gallery-worst-case-walk.json)
# at 1 m/s, 60 Hz, 4 memories, 4 m regions. Writes OUT/ (default chow2005/):
#   tables.md         Table 1 (update rate per memory), Table 2 (segments
#                     rendered per memory with and without segmentation),
#                     rendering load, tearing without and with warping,
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
  echo "| run | triangles/s | load reduction vs everything every frame | tear pixels/frame | pixels showing nothing | mean PSNR (dB) | largest warp (px) | host CPU (ms/frame) |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
  for r in segmented warped unsegmented objects; do
    f="$OUT/$r.json"
    warp=$(grep -q '"max_warp_displacement_px"' "$f" && awk -v v="$(value max_warp_displacement_px "$f")" 'BEGIN { printf "%.1f", v }' || echo "-")
    printf "| %s | %.2f M | %.2fx | %.1f | %.1f | %.2f | %s | %.1f |\n" "$r" \
      "$(awk -v v="$(value triangles_per_s "$f")" 'BEGIN { print v / 1e6 }')" "$(value load_reduction "$f")" \
      "$(value mean_tear_pixels "$f")" "$(value mean_tear_gap_pixels "$f")" "$(value mean_psnr_db "$f")" "$warp" \
      "$(value host_wall_ms_per_frame "$f")"
  done
} > "$OUT/tables.md"
cat "$OUT/tables.md"
echo "written $OUT/tables.md"
