#!/usr/bin/env bash
# Set-up, build, and the benchmark: docs/benchmark/bench.{csv,md} and its two plots, from the
# shared dragon (sampled to 640,826 points) and bunny. Extra arguments go to sss_bench (e.g.
# --quick, or a file and --mm-per-unit). References are cached in ~/.cache/sss. Long: on a
# software rasteriser the accurate settings take minutes per row.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
./build/examples/sss_bench --out docs/benchmark "$@"
