#!/usr/bin/env bash
# Builds the whole test suite with AddressSanitizer and
# UndefinedBehaviorSanitizer (clang, in build-sanitize/ apart from the fuzz
# targets) and runs it. Too slow for the test command on two cores; docs/reliability.md
# gives its last result.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
CC=clang CXX=clang++ cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DCAUSTICA_FUZZ=ON >/dev/null
cmake --build build-sanitize --parallel "$(nproc)"
# The statistical tests' sample counts are sized for an optimised build; the
# sanitised one is several times slower, hence the long timeout.
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-sanitize -E '^(fuzz-|format$|bench$)' --output-on-failure --timeout 7200 -j "$(nproc)"
