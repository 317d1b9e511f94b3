#!/usr/bin/env bash
# Fuzzes the Oculus report decoder with libFuzzer (clang, ASan + UBSan) for
# SECONDS (default 60), starting from a corpus of valid DK1/DK2 reports.
# The ordinary tests run the same target over 200 000 fixed inputs
# (ReportDecoderFuzz.RandomAndMutatedReports); this is the open-ended search.
# Usage: scripts/fuzz.sh [SECONDS]   (needs clang and libclang-rt-dev)
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_TO_RUN=${1:-60}
command -v clang++ >/dev/null || { echo "fuzz.sh: needs clang++ (apt-get install clang libclang-rt-dev)" >&2; exit 2; }
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DARPSIM_FUZZ=ON -DARPSIM_WERROR=OFF -DARPSIM_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target arp_fuzz_report_decoder
corpus=build-fuzz/fuzz-corpus
mkdir -p "$corpus"
# Seeds: one valid report of each model (first byte 0: DK1, 1: DK2).
printf '\x00\x01\x01\xe8\x03\x05\x00\xc4\x09' > "$corpus/dk1-seed"; head -c 56 /dev/zero >> "$corpus/dk1-seed"
printf '\x01\x0b\x05\x00\x01\x10\x00\xc4\x09\x40\x42\x0f\x00' > "$corpus/dk2-seed"; head -c 52 /dev/zero >> "$corpus/dk2-seed"
build-fuzz/tests/arp_fuzz_report_decoder -max_total_time="$SECONDS_TO_RUN" -max_len=128 "$corpus"
