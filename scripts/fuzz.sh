#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (tests/fuzz/, against build/), replays every kept
# regression input and the generated seeds, then fuzzes each target for SSS_FUZZ_SECONDS
# (default 60) from a corpus kept in build-fuzz/, with the random seed SSS_FUZZ_SEED (default 1;
# another seed, or a longer time, explores further). A crashing input is copied into
# tests/fuzz/regressions/<target>/ (commit it: it is replayed on every run from then on),
# printed in base64, and the script fails. Needs build/ (scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${SSS_FUZZ_SECONDS:-60}"
seed="${SSS_FUZZ_SEED:-1}"  # fixed: a fresh checkout (CI) fuzzes the same inputs each run
mkdir -p build-fuzz
cmake -S tests/fuzz -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ -DSSS_BUILD_DIR="$PWD/build" > build-fuzz/configure.log 2>&1 \
  || { cat build-fuzz/configure.log; exit 1; }
cmake --build build-fuzz -j"$(nproc)"
rm -rf build-fuzz/seeds
build-fuzz/make_fuzz_seeds build-fuzz/seeds
status=0
for target in load_cloud cli_options; do
  corpus="build-fuzz/corpus/$target" crashes="build-fuzz/crashes/$target"
  regressions="tests/fuzz/regressions/$target"
  mkdir -p "$corpus" "$crashes"
  echo "== fuzz_$target: replaying $(ls "$regressions" | wc -l) kept inputs and $(ls build-fuzz/seeds/$target | wc -l) seeds"
  if ! build-fuzz/fuzz_$target -runs=0 "$regressions" "build-fuzz/seeds/$target" \
       > "build-fuzz/$target.replay.log" 2>&1; then
    grep -E "ERROR|SUMMARY|runtime error|Assertion|Running: " "build-fuzz/$target.replay.log" \
      | head -20 || true
    echo "fuzz_$target: a kept input or a seed fails again"
    exit 1
  fi
  tail -1 "build-fuzz/$target.replay.log"
  echo "== fuzz_$target: fuzzing for $seconds s"
  before=$(ls "$crashes" | wc -l)
  if ! build-fuzz/fuzz_$target -seed="$seed" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=25 \
       -artifact_prefix="$crashes/" "$corpus" "build-fuzz/seeds/$target" > "build-fuzz/$target.log" 2>&1; then
    status=1
    grep -E "ERROR|SUMMARY|==[0-9]+==" "build-fuzz/$target.log" | head -20 || true
    for crash in $(ls -t "$crashes" | head -n $(( $(ls "$crashes" | wc -l) - before ))); do
      cp "$crashes/$crash" "$regressions/$crash"
      echo "fuzz_$target: crashing input kept as $regressions/$crash (base64 below)"
      base64 "$crashes/$crash"
    done
  fi
  grep -E "^Done [0-9]+ runs" "build-fuzz/$target.log" || tail -3 "build-fuzz/$target.log"
done
exit $status
