#!/usr/bin/env bash
# Installs (idempotently) the Debian packages SeaSpring needs to build, test and run its
# Python tools. Safe to run repeatedly: it only calls apt-get when something is missing.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libeigen3-dev libhdf5-dev libpugixml-dev libgtest-dev libcli11-dev
  python3 python3-numpy python3-h5py python3-matplotlib
  paraview python3-paraview xvfb xauth
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 || { echo "setup-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup-deps: done"
