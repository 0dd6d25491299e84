#!/usr/bin/env bash
# Runs ParaView's pvbatch on N ranks, or its GUI, or a pvserver and its Python client, with
# the plugin at hand:
#   bash scripts/pvbatch.sh [-np N | --gui | --client-server N] SCRIPT.py [ARGS...]
# (-np 1, the default, runs pvbatch alone; more runs `mpirun -np N pvbatch`; --gui runs
# `paraview --script=SCRIPT.py --exit` with ARGS in SSS_SCRIPT_ARGS as JSON, since the GUI hands
# a script none, and with settings of its own that keep the welcome dialog shut;
# --client-server N starts `mpirun -np N pvserver` on a free port, runs SCRIPT.py in python3
# with ARGS and `--url cs://localhost:PORT`, for the script to Connect() to, then prints the
# server's log; Debian's pvpython from the unpacked package loads Debian's VTK 9.1 Python
# modules before ParaView's and crashes, python3 with ParaView's on PYTHONPATH does not). Sets
# SSS_PARAVIEW_PLUGIN to the plugin this checkout built (build/paraview), puts the unpacked
# python3-paraview on PYTHONPATH when that package is not installed (Debian will not install it
# beside python3-vtk9; scripts/setup.sh unpacks it into .deps/), lets Open MPI run as root, and
# starts an Xvfb server for the run when there is no DISPLAY (Debian's ParaView draws with GLX).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ranks=1
gui=0
servers=0
if [ "${1:-}" = "-np" ]; then
  ranks="$2"
  shift 2
elif [ "${1:-}" = "--gui" ]; then
  gui=1
  shift
elif [ "${1:-}" = "--client-server" ]; then
  servers="$2"
  shift 2
fi
[ $# -ge 1 ] || { echo "usage: $0 [-np N | --gui | --client-server N] SCRIPT.py [ARGS...]" >&2; exit 2; }
export SSS_PARAVIEW_PLUGIN="${SSS_PARAVIEW_PLUGIN:-$root/build/paraview/lib/paraview-5.11/plugins/TranslucentPointClouds/TranslucentPointClouds.so}"
[ -f "$SSS_PARAVIEW_PLUGIN" ] || { echo "$0: no plugin at $SSS_PARAVIEW_PLUGIN: run scripts/build.sh" >&2; exit 1; }
unpacked="$root/.deps/python3-paraview/usr/lib/python3/dist-packages"
if ! dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null | grep -q "install ok installed"; then
  [ -d "$unpacked/paraview" ] || { echo "$0: python3-paraview is neither installed nor unpacked: run scripts/setup.sh" >&2; exit 1; }
  export PYTHONPATH="$unpacked${PYTHONPATH:+:$PYTHONPATH}"
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# What this run started or made, gone before it ends, so that a next run cannot meet it.
xvfb="" server="" scratch=""
clean_up() {
  for process in $server $xvfb; do
    kill "$process" 2> /dev/null || true
    wait "$process" 2> /dev/null || true
  done
  [ -z "$scratch" ] || rm -rf "$scratch"
}
trap clean_up EXIT
if [ -z "${DISPLAY:-}" ]; then
  # One Xvfb for all ranks, on the first free display, ready before they connect.
  n=90
  while [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ]; do n=$((n + 1)); done
  Xvfb ":$n" -screen 0 1280x1024x24 -nolisten tcp -noreset > /dev/null 2>&1 &
  xvfb=$!
  # Ready when a client can connect; -noreset: the server must not restart when that client
  # (or a rank) disconnects while other ranks connect.
  for _ in $(seq 200); do xdpyinfo -display ":$n" > /dev/null 2>&1 && break; sleep 0.05; done
  xdpyinfo -display ":$n" > /dev/null 2>&1 || { echo "$0: Xvfb did not start on :$n" >&2; exit 1; }
  export DISPLAY=":$n"
fi
if [ "$gui" = 1 ]; then
  # A settings folder of the run's own: no welcome dialog (it would wait for a click), and
  # nothing of the user's settings changes the view.
  scratch=$(mktemp -d)
  settings="$scratch"
  version=$(/usr/bin/paraview --version 2> /dev/null | sed -n 's/^paraview version //p')
  mkdir -p "$settings/.config/ParaView"
  printf '[General]\nGeneralSettings.ShowWelcomeDialog=0\n' \
    > "$settings/.config/ParaView/ParaView$version.ini"
  script="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
  shift
  SSS_SCRIPT_ARGS=$(/usr/bin/python3 -c 'import json, sys; print(json.dumps(sys.argv[1:]))' "$@") \
    HOME="$settings" XDG_RUNTIME_DIR="$settings" /usr/bin/paraview --script="$script" --exit
elif [ "$servers" -gt 0 ]; then
  port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("localhost", 0)); print(s.getsockname()[1])')
  scratch=$(mktemp -d)
  server_log="$scratch/pvserver.log"
  mpirun --oversubscribe -np "$servers" -x PYTHONPATH -x SSS_PARAVIEW_PLUGIN -x DISPLAY \
    /usr/bin/pvserver -v=INFO --server-port="$port" > "$server_log" 2>&1 &
  server=$!
  for _ in $(seq 600); do
    grep -q "Accepting connection" "$server_log" && break
    kill -0 "$server" 2> /dev/null || { cat "$server_log" >&2; echo "$0: pvserver ended before it took a connection" >&2; exit 1; }
    sleep 0.1
  done
  /usr/bin/python3 "$@" --url "cs://localhost:$port"
  wait "$server"  # pvserver ends when its client disconnects
  cat "$server_log"
elif [ "$ranks" -gt 1 ]; then
  mpirun --oversubscribe -np "$ranks" -x PYTHONPATH -x SSS_PARAVIEW_PLUGIN -x DISPLAY \
    /usr/bin/pvbatch "$@"
else
  /usr/bin/pvbatch "$@"
fi
