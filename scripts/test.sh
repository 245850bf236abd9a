#!/usr/bin/env bash
# Builds caustica and runs the whole test suite with ctest, then builds the
# fuzz targets (clang, sanitizers) and runs each for a short fixed time.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
ctest --test-dir build --output-on-failure --timeout 1200 -j "$(nproc)"
scripts/fuzz.sh 15 1
