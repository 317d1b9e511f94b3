#!/usr/bin/env bash
# Installs the Debian packages arpsim needs. Idempotent: packages already
# present are skipped, so a second run does no network access at all.
# Extra packages a script needs beyond the build's (scripts/fuzz.sh: clang)
# are given as arguments.
set -euo pipefail
PKGS=(
  build-essential cmake pkg-config
  libgtest-dev libgmock-dev libbenchmark-dev
  libopenimageio-dev openimageio-tools
  libglm-dev libcli11-dev nlohmann-json3-dev
  libusb-1.0-0-dev umockdev libumockdev-dev
  libsdl2-dev xvfb xauth
  libsystemc-dev
  libassimp-dev assimp-testmodels glmark2-data gnuplot-nox
  verilator yosys
  libegl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri
  "$@"
)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "setup: all packages present"
fi
