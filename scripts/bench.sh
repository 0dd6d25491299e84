#!/usr/bin/env bash
# Set-up, build, and the benchmark: docs/benchmark/bench.{csv,md} and its two plots, from the
# shared scans at their real scale (the dragon sampled to 640,826 points, the bunny, the two
# Kinect scenes, the LiDAR tile). Extra arguments go to sss_bench (e.g. --quick, --settings,
# --materials, or a file and --mm-per-unit). References are cached in ~/.cache/sss. Long: on a
# software rasteriser a light move on the large scans takes minutes per row.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
./build/programs/sss_bench --out docs/benchmark "$@"
