#!/usr/bin/env bash
# Set-up, build, and the main job: the CPU reference renders the procedural marble torus,
# lit from behind and above, to demo.png (plus demo.pfm and demo.json).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
./build/examples/sss_render --output demo.png --linear demo.pfm --stats demo.json "$@"
