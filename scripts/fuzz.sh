#!/usr/bin/env bash
# Builds the fuzz targets (clang, with AddressSanitizer and
# UndefinedBehaviorSanitizer) in build-fuzz/ and runs each for SECONDS
# (default 20) with libFuzzer's SEED (default 0: a fresh one each run; the
# test command fixes it so its runs repeat), two at a time. An hour in all:
#   scripts/fuzz.sh 1200
# Inputs that crash are left in build-fuzz/tests/fuzz/findings/; each one
# found becomes a regression input in tests/fuzz/regressions/<target>/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-20}"
seed="${2:-0}"
scripts/install-deps.sh
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DCAUSTICA_FUZZ=ON -DCAUSTICA_UNITY_ENGINE=ON \
  -DCAUSTICA_FUZZ_SECONDS="$seconds" -DCAUSTICA_FUZZ_SEED="$seed" >/dev/null
cmake --build build-fuzz --target fuzzers --parallel "$(nproc)"
ctest --test-dir build-fuzz -R '^fuzz-' --output-on-failure --timeout $((seconds + 300)) -j 2
