#!/usr/bin/env bash
# Installs the dependencies if needed, then configures and builds caustica
# (Release) in build/. Safe to run again: both steps are incremental.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --parallel "$(nproc)"
