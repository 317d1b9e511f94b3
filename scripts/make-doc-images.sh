#!/usr/bin/env bash
# Regenerates the images in docs/images/ with arpsim frame: the calibration
# cube seen at yaw 0/90/180/270, pitch +-90, and one oblique view across a corner.
set -euo pipefail
cd "$(dirname "$0")/.."
B=${ARPSIM:-build/apps/arpsim/arpsim}
mkdir -p docs/images
run() { "$B" frame "$@" >/dev/null; }
run --yaw 0 --out docs/images/calibration_yaw0.png
run --yaw 90 --out docs/images/calibration_yaw90.png
run --yaw 180 --out docs/images/calibration_yaw180.png
run --yaw 270 --out docs/images/calibration_yaw270.png
run --pitch 90 --out docs/images/calibration_pitch+90.png
run --pitch -90 --out docs/images/calibration_pitch-90.png
run --yaw 45 --pitch 35 --roll 10 --out docs/images/calibration_corner.png
echo "docs/images: $(ls docs/images | wc -l) images"
