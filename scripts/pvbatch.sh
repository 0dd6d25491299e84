#!/usr/bin/env bash
# Runs ParaView's pvbatch on N ranks, or its GUI, with the plugin at hand:
#   bash scripts/pvbatch.sh [-np N | --gui] SCRIPT.py [ARGS...]
# (-np 1, the default, runs pvbatch alone; more runs `mpirun -np N pvbatch`; --gui runs
# `paraview --script=SCRIPT.py --exit` with ARGS in SSS_SCRIPT_ARGS as JSON, since the GUI hands
# a script none, and with settings of its own that keep the welcome dialog shut). Sets
# SSS_PARAVIEW_PLUGIN to the plugin this checkout built (build/paraview), puts the unpacked
# python3-paraview on PYTHONPATH when that package is not installed (Debian will not install it
# beside python3-vtk9; scripts/setup.sh unpacks it into .deps/), lets Open MPI run as root, and
# starts an Xvfb server for the run when there is no DISPLAY (Debian's ParaView draws with GLX).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ranks=1
gui=0
if [ "${1:-}" = "-np" ]; then
  ranks="$2"
  shift 2
elif [ "${1:-}" = "--gui" ]; then
  gui=1
  shift
fi
[ $# -ge 1 ] || { echo "usage: $0 [-np N | --gui] SCRIPT.py [ARGS...]" >&2; exit 2; }
export SSS_PARAVIEW_PLUGIN="${SSS_PARAVIEW_PLUGIN:-$root/build/paraview/lib/paraview-5.11/plugins/TranslucentPointClouds/TranslucentPointClouds.so}"
[ -f "$SSS_PARAVIEW_PLUGIN" ] || { echo "$0: no plugin at $SSS_PARAVIEW_PLUGIN: run scripts/build.sh" >&2; exit 1; }
unpacked="$root/.deps/python3-paraview/usr/lib/python3/dist-packages"
if ! dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null | grep -q "install ok installed"; then
  [ -d "$unpacked/paraview" ] || { echo "$0: python3-paraview is neither installed nor unpacked: run scripts/setup.sh" >&2; exit 1; }
  export PYTHONPATH="$unpacked${PYTHONPATH:+:$PYTHONPATH}"
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
if [ -z "${DISPLAY:-}" ]; then
  # One Xvfb for all ranks, on the first free display, ready before they connect.
  n=90
  while [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ]; do n=$((n + 1)); done
  Xvfb ":$n" -screen 0 1280x1024x24 -nolisten tcp -noreset > /dev/null 2>&1 &
  xvfb=$!
  # Gone before this script ends, so that a next run cannot meet it on the same display.
  trap 'kill "$xvfb" 2> /dev/null; wait "$xvfb" 2> /dev/null || true' EXIT
  # Ready when a client can connect; -noreset: the server must not restart when that client
  # (or a rank) disconnects while other ranks connect.
  for _ in $(seq 200); do xdpyinfo -display ":$n" > /dev/null 2>&1 && break; sleep 0.05; done
  xdpyinfo -display ":$n" > /dev/null 2>&1 || { echo "$0: Xvfb did not start on :$n" >&2; exit 1; }
  export DISPLAY=":$n"
fi
if [ "$gui" = 1 ]; then
  # A settings folder of the run's own: no welcome dialog (it would wait for a click), and
  # nothing of the user's settings changes the view.
  settings=$(mktemp -d)
  trap 'rm -rf "$settings"; [ -z "${xvfb:-}" ] || { kill "$xvfb" 2> /dev/null; wait "$xvfb" 2> /dev/null || true; }' EXIT
  version=$(/usr/bin/paraview --version 2> /dev/null | sed -n 's/^paraview version //p')
  mkdir -p "$settings/.config/ParaView"
  printf '[General]\nGeneralSettings.ShowWelcomeDialog=0\n' \
    > "$settings/.config/ParaView/ParaView$version.ini"
  script="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
  shift
  SSS_SCRIPT_ARGS=$(/usr/bin/python3 -c 'import json, sys; print(json.dumps(sys.argv[1:]))' "$@") \
    HOME="$settings" XDG_RUNTIME_DIR="$settings" /usr/bin/paraview --script="$script" --exit
elif [ "$ranks" -gt 1 ]; then
  mpirun --oversubscribe -np "$ranks" -x PYTHONPATH -x SSS_PARAVIEW_PLUGIN -x DISPLAY \
    /usr/bin/pvbatch "$@"
else
  /usr/bin/pvbatch "$@"
fi
