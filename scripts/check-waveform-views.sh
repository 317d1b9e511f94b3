#!/usr/bin/env bash
# Opens each committed GTKWave view with its waveform in a real GTKWave
# (under Xvfb) and checks that every signal of the VCD is displayed and that
# the view opens where something moves: value changes inside the visible
# time window.
# Needs the Debian packages gtkwave, xvfb and xauth (not part of the test
# command: a desktop tool). Run after building.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v gtkwave >/dev/null && command -v xvfb-run >/dev/null ||
  { echo "check-waveform-views: needs gtkwave and xvfb-run (apt-get install gtkwave xvfb xauth)" >&2; exit 2; }
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
BENCHES=${BENCHES:-build/testbench/arp_sc_benches}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/count.tcl" <<'TCL'
puts "displayed [llength [gtkwave::getDisplayedSignals]]"
puts "window [gtkwave::getWindowStartTime] [gtkwave::getZoomFactor]"
gtkwave::/File/Quit
TCL
"$ARPSIM" run -q --fidelity detailed --frames 1 --every 0 --vcd "$tmp/arp.vcd" --vcd-lines 0:2 >/dev/null
"$ARPSIM" latency -q --frames 30 --no-sweeps --out-dir "$tmp/lat" >/dev/null  # the apparatus oscilloscope
pairs=("$tmp/arp.vcd waveforms/arp.gtkw" "testbench/systemc/golden/tiny_rtl.vcd waveforms/tiny_rtl.gtkw"
       "$tmp/lat/apparatus.vcd $tmp/lat/apparatus.gtkw")
for g in waveforms/bench_*.gtkw; do
  m=$(basename "$g" .gtkw); m=${m#bench_}
  ARPSIM_BENCH_VCD="$tmp" "$BENCHES" --gtest_filter="ModuleBench.$m" >/dev/null
  pairs+=("$tmp/bench_$m.vcd $g")
done
status=0
for p in "${pairs[@]}"; do
  set -- $p
  want=$(grep -c '^\$var' "$1")
  out=$(timeout 120 xvfb-run -a gtkwave -S "$tmp/count.tcl" "$1" "$2" 2>/dev/null)
  got=$(sed -n 's/^displayed //p' <<<"$out")
  # The view as GTKWave opened it: its start and zoom (2^-zoom ps per pixel), across the
  # 1000-pixel wave area the save file sizes for (the Xvfb window here is not laid out yet).
  read -r t0 zoom < <(sed -n 's/^window //p' <<<"$out")
  t1=$(awk -v a="${t0:-0}" -v z="${zoom:-0}" 'BEGIN { printf "%.0f", a + 2 ^ (-z) * 1000 }')
  # Value changes (lines after a timestamp that are not timestamps) inside [t0, t1].
  moving=$(awk -v a="${t0:-0}" -v b="${t1:-0}" '/^\$enddefinitions/ {body = 1; next} body && /^#/ {t = substr($0, 2) + 0; next}
            body && t >= a && t <= b && NF {n++} END {print n + 0}' "$1")
  printf "%-40s %3s of %3s signals displayed; window %s..%s ps, %s value changes in it\n" "$2" "${got:-0}" "$want" "${t0:-?}" "${t1:-?}" "$moving"
  [ "${got:-0}" = "$want" ] && [ "$moving" -gt 0 ] || status=1
done
exit $status
