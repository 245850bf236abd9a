#!/usr/bin/env bash
# Fails, listing the files, if any C++ source differs from .clang-format's layout.
set -euo pipefail
clang_format=${1:-clang-format}
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files -co --exclude-standard '*.h' '*.cpp')
[ ${#files[@]} -gt 0 ] || exit 0
"$clang_format" --dry-run --Werror "${files[@]}"
