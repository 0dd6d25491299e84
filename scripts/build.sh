#!/usr/bin/env bash
# Configures and builds into build/ (Release); extra arguments go to cmake.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p build
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSSS_BUILD_EXAMPLES=ON -DSSS_BUILD_TESTS=ON "$@" > build/configure.log 2>&1 \
  || { cat build/configure.log; exit 1; }
cmake --build build -j"$(nproc)"
