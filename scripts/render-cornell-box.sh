#!/usr/bin/env bash
# Builds caustica and renders the default Cornell box to cornell-box.exr and
# cornell-box.png in the current folder. Extra arguments go to `caustica render`.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/build.sh"
"$root/build/caustica" render "$root/scenes/cornell-box.xml" -o cornell-box.exr "$@"
