#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds with; fast when all are present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libflann-dev liblz4-dev zlib1g-dev libgtest-dev
  libvtk9-dev python3-vtk9 python3-numpy libpcl-dev
  libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  xvfb xauth libglx-mesa0
  python3-matplotlib
  clang libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
