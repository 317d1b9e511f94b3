#!/usr/bin/env bash
# Instructions a simulated pixel clock at one fidelity level, counted by
# callgrind: a count the neighbours on a shared machine cannot move, where
# wall time moves by tens of per cent (docs/performance.md). The run is the
# timed-speed bench's (default configuration, head turning at 200 deg/s); the
# set-up is taken out by difference: the same run for FRAMES_B frames minus
# FRAMES_A frames, over the pixel clocks between them (the reports' own
# counts). Then the TOP functions of that difference, instructions per pixel
# clock each (a function's own instructions, not its callees').
# Needs valgrind (apt-get install valgrind). A detailed run takes about a
# minute under callgrind per frame.
# Usage: bench/instructions-per-clock.sh [LEVEL]   (env: ARPSIM, FRAMES_A=1, FRAMES_B=3, TOP=25)
set -euo pipefail
# A relative ARPSIM names a file from where the script was started; the default, from the repository.
if [ -n "${ARPSIM:-}" ]; then ARPSIM=$(realpath -m -- "$ARPSIM"); fi
cd "$(dirname "$0")/.."
LEVEL=${1:-detailed}
ARPSIM=${ARPSIM:-build/apps/arpsim/arpsim}
FRAMES_A=${FRAMES_A:-1}
FRAMES_B=${FRAMES_B:-3}
TOP=${TOP:-25}
command -v valgrind >/dev/null || { echo "instructions-per-clock.sh: valgrind not found (apt-get install valgrind)" >&2; exit 1; }
[ -x "$ARPSIM" ] || { echo "instructions-per-clock.sh: $ARPSIM is not built" >&2; exit 1; }
(( FRAMES_B > FRAMES_A )) || { echo "instructions-per-clock.sh: FRAMES_B ($FRAMES_B) must exceed FRAMES_A ($FRAMES_A)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
count() {  # frames -> callgrind output in $tmp/cg.<frames>, report in $tmp/r.<frames>.json
  valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.$1" "$ARPSIM" run -q --fidelity "$LEVEL" --frames "$1" \
    --every 0 --motion rotate --rate 200 --report "$tmp/r.$1.json" 2>"$tmp/log.$1" >/dev/null \
    || { echo "instructions-per-clock.sh: the run of $1 frames failed:" >&2; tail -5 "$tmp/log.$1" >&2; exit 1; }
}
count "$FRAMES_A"
count "$FRAMES_B"
python3 - "$tmp" "$FRAMES_A" "$FRAMES_B" "$TOP" "$LEVEL" <<'EOF'
import json, re, subprocess, sys
tmp, a, b, top, level = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
def functions(frames):
    out = subprocess.run(["callgrind_annotate", "--threshold=100", f"{tmp}/cg.{frames}"],
                         capture_output=True, text=True, check=True).stdout
    total = int(re.search(r"([\d,]+) \(100\.0%\)\s+PROGRAM TOTALS", out).group(1).replace(",", ""))
    per = {}
    for line in out.splitlines():
        # "  N (P%)  FILE:FUNCTION [OBJECT]": keyed by the whole signature (a name cut at its first
        # parenthesis would merge every "(anonymous namespace)" function, and a lambda with its owner).
        m = re.match(r"\s*([\d,]+) \([^)]*\)\s+\S*?:(.*) \[[^\]]*\]$", line)
        if m: per[m.group(2)] = per.get(m.group(2), 0) + int(m.group(1).replace(",", ""))
    return total, per
def clocks(frames):
    return json.load(open(f"{tmp}/r.{frames}.json"))["simulation"]["pixel_clocks"]
ta, fa = functions(a)
tb, fb = functions(b)
n = clocks(b) - clocks(a)
if n <= 0: sys.exit("instructions-per-clock.sh: no pixel clocks between the two runs")
print(f"{level}: {(tb - ta) / n:.1f} instructions a simulated pixel clock "
      f"({tb - ta} instructions over {n} pixel clocks, frames {a} to {b})")
rows = sorted(((fb.get(k, 0) - fa.get(k, 0)) / n, k) for k in set(fa) | set(fb))[::-1]
for v, k in rows[:top]: print(f"{v:9.1f}  {k[:160]}")
EOF
