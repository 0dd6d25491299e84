#!/usr/bin/env bash
# Installs the Debian 12 packages the project builds with; fast when all are present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libflann-dev liblz4-dev zlib1g-dev libgtest-dev
  libvtk9-dev python3-vtk9 python3-numpy libpcl-dev
  libosmesa6-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
  xvfb xauth libglx-mesa0 x11-utils
  python3-matplotlib
  clang libclang-rt-14-dev
  paraview paraview-dev openmpi-bin
)

# python3-paraview (pvbatch's Python modules, and the wrapping hierarchy the ParaView plugin
# builds with) conflicts with python3-vtk9, which libvtk9-dev needs: it is unpacked into .deps/
# instead of installed (scripts/pvbatch.sh and the plugin's build use it from there).
unpack_python3_paraview() {
  local dir="$PWD/.deps/python3-paraview"
  dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null | grep -q "install ok installed" && return 0
  [ -f "$dir/unpacked" ] && return 0
  local tmp
  tmp="$(mktemp -d)"
  (cd "$tmp" && { apt-get download python3-paraview > /dev/null 2>&1 \
     || { $SUDO apt-get update -q > /dev/null && apt-get download python3-paraview > /dev/null; }; })
  rm -rf "$dir" && mkdir -p "$dir"
  dpkg-deb -x "$tmp"/python3-paraview_*.deb "$dir"
  rm -rf "$tmp"
  touch "$dir/unpacked"
  echo "setup: python3-paraview unpacked into .deps/python3-paraview"
}

cd "$(dirname "$0")/.."
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
else
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
unpack_python3_paraview
