#!/usr/bin/env bash
# Set-up, build, and every test: the release suite (core, hard cases, the GPU path on EGL and
# OSMesa with DISPLAY unset, shared scans, the PCL glue, Python, install, the benchmark's quick
# mode); fuzzing of the loaders and the option parser (scripts/fuzz.sh); then a build with
# AddressSanitizer and UndefinedBehaviorSanitizer of the core, the PCL glue, sss_render and the
# GPU path, and their tests again (the accuracy sweeps excepted, below: the same code paths
# over millions of sources, too long under the sanitizers).
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
  -DSSS_BUILD_EXAMPLES=ON -DSSS_WRAP_PYTHON=OFF -DSSS_PARAVIEW_PLUGIN=OFF > build-sanitize/configure.log 2>&1 \
  || { cat build-sanitize/configure.log; exit 1; }
cmake --build build-sanitize -j"$(nproc)" --target sss_core_tests sss_pcl_tests sss_render \
  sss_render_input_tests sss_gpu_tests sss_gpu_splat_tests sss_backend_tests
export ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp" \
  UBSAN_OPTIONS=print_stacktrace=1
# Core, less the sweeps that run millions of sources through the same code as smaller tests
# (the two-kernel model's two references, the box edge's sixteen noisy clouds: 183 s and 69 s
# under the sanitizers).
ctest --test-dir build-sanitize --output-on-failure -L core -j1 \
  -E 'Spacings/Slab|Spacings/RandomSlab.*/marble|HardCases.NoAbsorption|HardCases.IndexOfOneHasNoFresnelLoss|HardCases.UnitsAndFarOrigins|HardCases.TinyAndHugeKernelsOnOneModel|DenoisedSurface.BoxEdgeKeepsBothFacesNormals'
# The PCL glue: every loader, encoding and refusal; the lying headers' messages are printed.
ctest --test-dir build-sanitize --output-on-failure -j1 -R '^PclGlue' -E 'LyingHeaders'
ctest --test-dir build-sanitize -V -j1 -R '^PclGlue.LyingHeaders' > build-sanitize/lying.log 2>&1 \
  || { cat build-sanitize/lying.log; exit 1; }
grep -E "lying header|tests passed" build-sanitize/lying.log
# The plugin and sss_render on EGL and OSMesa: sss_render's refusals and an organised scan,
# the pass's bad inputs (the two 1000-frame soaks included), the caching of steps, the splat
# views and the two backends' agreement. The accuracy tests run the same code paths over many
# clouds and materials (about 15 minutes in release) and stay in the release suite. Leak
# checking is off here: llvmpipe's JIT-compiled shaders allocate from code with no module
# (56-byte blocks per shader variant), which LeakSanitizer can neither attribute nor suppress;
# the soaks bound resident memory in the release suite instead.
ASAN_OPTIONS=detect_leaks=0 ctest --test-dir build-sanitize --output-on-failure -j1 \
  -R '^(RenderInput|GpuBadInput|GpuCaching|GpuSplats|Backends)\.'
