#!/usr/bin/env bash
# Installs (idempotently) the Debian packages SeaSpring needs to build, test and run its
# Python tools. Safe to run repeatedly: it only calls apt-get when something is missing.
# ParaView (for tools/paraview_check.py and its test) is installed after the rest and is not
# fatal: without it the ParaView test skips visibly and validate.py draws no pictures.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libeigen3-dev libhdf5-dev libpugixml-dev libgtest-dev libcli11-dev
  python3 python3-numpy python3-h5py python3-matplotlib
  clang libomp-dev
)
optional=(paraview python3-paraview xvfb xauth ffmpeg)

missingOf() {
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || echo "$p"
  done
}
mapfile -t missing < <(missingOf "${packages[@]}")
mapfile -t missing_optional < <(missingOf "${optional[@]}")

if [ ${#missing[@]} -eq 0 ] && [ ${#missing_optional[@]} -eq 0 ]; then
  echo "setup-deps: all $((${#packages[@]} + ${#optional[@]})) packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 || { echo "setup-deps: need root or sudo to install: ${missing[*]} ${missing_optional[*]}" >&2; exit 1; }
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup-deps: installing ${missing[*]}"
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if [ ${#missing_optional[@]} -gt 0 ]; then
  echo "setup-deps: installing ${missing_optional[*]} (ParaView; optional)"
  $SUDO apt-get install -y -qq --no-install-recommends "${missing_optional[@]}" ||
    echo "setup-deps: WARNING: ParaView could not be installed; its test will skip" >&2
fi
echo "setup-deps: done"
