#!/usr/bin/env bash
# Set-up, build, and every test: the release suite (core, hard cases, the GPU path on EGL and
# OSMesa with DISPLAY unset, shared scans), then the
# core tests again built with AddressSanitizer and UndefinedBehaviorSanitizer. The slab
# accuracy sweep, the randomly sampled marble slabs (ketchup's, smaller, stay), the no-absorption and index-one slabs and the units test (millions of
# sources, the same code paths as the smaller tests) run in the release suite only: under the sanitizers they take too long.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
echo "== release build: all tests"
ctest --test-dir build --output-on-failure -j1
echo "== fuzzing: the loaders and the option parser, ${SSS_FUZZ_SECONDS:-60} s each"
bash scripts/fuzz.sh
echo "== ASan + UBSan build: core, the PCL glue, sss_render, and the GPU path on EGL and OSMesa"
mkdir -p build-sanitize
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSSS_SANITIZE=ON \
  -DSSS_BUILD_EXAMPLES=ON -DSSS_WRAP_PYTHON=OFF > build-sanitize/configure.log 2>&1 \
  || { cat build-sanitize/configure.log; exit 1; }
cmake --build build-sanitize -j"$(nproc)" --target sss_core_tests sss_pcl_tests sss_render \
  sss_render_input_tests sss_gpu_tests sss_gpu_splat_tests sss_backend_tests
export ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp" \
  UBSAN_OPTIONS=print_stacktrace=1
# Core, less the sweeps that run millions of sources through the same code as smaller tests.
ctest --test-dir build-sanitize --output-on-failure -L core -j1 \
  -E 'Spacings/Slab|Spacings/RandomSlab.*/marble|HardCases.NoAbsorption|HardCases.IndexOfOneHasNoFresnelLoss|HardCases.UnitsAndFarOrigins'
# The plugin, the PCL glue and sss_render: every loader and refusal, the pass's bad inputs
# (the 1000-frame soaks included), the splat views, the caching of steps, the two backends
# (sss_render on OSMesa and EGL), and one GPU-vs-reference scene per step-2 regime; the
# accuracy sweeps over many clouds run in the release suite only (same code, hours here).
ctest --test-dir build-sanitize --output-on-failure -j1 \
  -R '^(PclGlue|RenderInput|GpuBadInput|GpuCaching|GpuSplats|Backends)\.'
