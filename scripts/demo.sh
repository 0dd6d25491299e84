#!/usr/bin/env bash
# Set-up, build, and the main job: the real-time GPU method on a headless EGL context renders
# the procedural marble torus, lit from behind, to demo.png (plus demo.pfm, demo.ply and
# demo.json). Extra arguments go to sss_render (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
env -u DISPLAY ./build/programs/sss_render --light-dir 0.2,1,-0.3 --view-dir 0,-1,0.5 \
  --output demo.png --linear demo.pfm --bake demo.ply --stats demo.json "$@"
